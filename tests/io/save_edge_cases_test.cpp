// Saves to odd places and loads from odd files: temporary files of killed saves, names at the
// file system's limit, symbolic links, FIFOs, devices, huge files, a full disk, a read-only folder.
#include <gtest/gtest.h>

#include <sched.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "io/atomic_file.hpp"
#include "io_test_support.hpp"
#include "save_dir_fixture.hpp"
#include "verve/io.hpp"

namespace fs = std::filesystem;

namespace verve {
namespace {

using SaveEdgeCases = iotest::SaveDir;
using iotest::fileBytes;

Agent smallAgent() { return iotest::trainedAgent(iotest::mixedDescriptor(1), 50); }

// The full lattice of 2 sensors at resolution 90 (8100 RBFs): about 400 kB of XML.
Agent mediumAgent() {
    AgentDescriptor d;
    d.addContinuousSensor().addContinuousSensor();
    d.resolution = 90;
    d.numActions = 4;
    d.allocation = RbfAllocation::Full;
    return iotest::trainedAgent(d, 300, 2);
}

// The message of the Io error `call` must throw.
template <typename F>
std::string ioErrorOf(F&& call) {
    try {
        call();
    } catch (const Error& e) {
        return e.code() == ErrorCode::Io ? e.what() : "not an Io error: " + std::string(e.what());
    }
    return "no error";
}

TEST_F(SaveEdgeCases, AKilledSavesTemporaryFileIsRemovedByTheNextSave) {
    const Agent agent = mediumAgent();
    const std::string xml = saveAgentToString(agent);
    const fs::path target = dir_ / "agent.xml";
    std::mt19937 rng(7);
    for (int attempt = 0; attempt < 200 && leftovers().empty(); ++attempt) {
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {  // the file part of saveAgent only, so that kills land in it
            for (;;) io::writeFileAtomically(target.string(), xml);
        }
        std::this_thread::sleep_for(std::chrono::microseconds(500 + rng() % 5000));
        ::kill(child, SIGKILL);
        ::waitpid(child, nullptr, 0);
    }
    ASSERT_EQ(leftovers().size(), 1u) << "no kill landed inside a save";
    saveAgent(agent, target.string());
    EXPECT_TRUE(leftovers().empty());
    EXPECT_EQ(fileBytes(target), xml);
}

TEST_F(SaveEdgeCases, ASaveInProgressInAnotherProcessIsLeftAlone) {
    // Two processes save to the same file as fast as they can: the cleanup of one must never
    // remove the other's temporary file (that save would fail).
    const Agent a = smallAgent();
    const Agent b = iotest::trainedAgent(iotest::mixedDescriptor(2), 50);
    const fs::path target = dir_ / "agent.xml";
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        const int failures = failedSaves(a, target, 300);
        ::_exit(failures > 100 ? 100 : failures);
    }
    const int failures = failedSaves(b, target, 300);
    int status = 0;
    ::waitpid(child, &status, 0);
    EXPECT_EQ(failures, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "saves failed in the other process";
    EXPECT_TRUE(leftovers().empty());
    const std::string bytes = fileBytes(target);
    EXPECT_TRUE(bytes == saveAgentToString(a) || bytes == saveAgentToString(b));
}

TEST_F(SaveEdgeCases, ASaveInAnotherPidNamespaceIsLeftAlone) {
    // As the test above, with the other process in a PID namespace of its own (a container
    // sharing the folder): our pids mean nothing there and its pids nothing here, so neither may
    // take the other's temporary file for a killed save's (issue 32: kill(pid, 0) said ESRCH).
    const Agent a = smallAgent();
    const Agent b = iotest::trainedAgent(iotest::mixedDescriptor(2), 50);
    const fs::path target = dir_ / "agent.xml";
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        if (::unshare(CLONE_NEWPID) != 0) ::_exit(77);
        const pid_t inside = ::fork();  // pid 1 of the new namespace
        if (inside < 0) ::_exit(78);
        if (inside == 0) {
            const int failures = failedSaves(a, target, 400);
            ::_exit(failures > 100 ? 100 : failures);
        }
        int status = 0;
        ::waitpid(inside, &status, 0);
        ::_exit(WIFEXITED(status) ? WEXITSTATUS(status) : 99);
    }
    const int failures = failedSaves(b, target, 400);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    if (WEXITSTATUS(status) == 77) GTEST_SKIP() << "cannot make a PID namespace here (needs root or user namespaces)";
    EXPECT_EQ(failures, 0) << "saves failed here: the other namespace removed their temporary files";
    EXPECT_EQ(WEXITSTATUS(status), 0) << "saves failed in the other PID namespace";
    EXPECT_TRUE(leftovers().empty());
}

TEST_F(SaveEdgeCases, SavingOverAFileKeepsItsPermissionsAndOwner) {
    // A private save stays private (issue 32: the temporary file got the umask's 0644 and was
    // renamed over a 0600 save).
    const Agent agent = smallAgent();
    const fs::path target = dir_ / "agent.xml";
    for (const ::mode_t mode : {0600, 0640, 0604}) {
        saveAgent(agent, target.string());
        ASSERT_EQ(::chmod(target.c_str(), mode), 0);
        if (::geteuid() == 0) {
            ASSERT_EQ(::chown(target.c_str(), 65534, 65534), 0);
        }
        saveAgent(agent, target.string());
        struct stat st;
        ASSERT_EQ(::stat(target.c_str(), &st), 0);
        EXPECT_EQ(st.st_mode & 0777, mode) << std::oct << "mode " << mode << " became " << (st.st_mode & 0777);
        if (::geteuid() == 0) {
            EXPECT_EQ(st.st_uid, 65534u);
            EXPECT_EQ(st.st_gid, 65534u);
        }
        fs::remove(target);
    }
    // A new file gets the umask's permissions, as any file the game makes.
    const ::mode_t mask = ::umask(022);
    saveAgent(agent, target.string());
    ::umask(mask);
    struct stat st;
    ASSERT_EQ(::stat(target.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0644u);
}

TEST_F(SaveEdgeCases, NamesUpToTheFileSystemLimitSave) {
    const Agent agent = smallAgent();
    const std::string xml = saveAgentToString(agent);
    for (const std::size_t bytes : {239u, 240u, 250u, 255u}) {
        const fs::path target = dir_ / (std::string(bytes - 4, 'n') + ".xml");
        ASSERT_NO_THROW(saveAgent(agent, target.string())) << bytes << "-byte name";
        EXPECT_EQ(saveAgentToString(loadAgent(target.string())), xml) << bytes << "-byte name";
    }
    std::string utf8;  // 127 two-byte characters: the temporary name must not cut one in half
    for (int i = 0; i < 127; ++i) utf8 += "\xC3\xA9";
    ASSERT_NO_THROW(saveAgent(agent, (dir_ / utf8).string()));
    EXPECT_EQ(saveAgentToString(loadAgent((dir_ / utf8).string())), xml);

    const fs::path tooLong = dir_ / std::string(256, 'n');
    EXPECT_NE(ioErrorOf([&] { saveAgent(agent, tooLong.string()); }).find("too long"), std::string::npos);
    EXPECT_TRUE(leftovers().empty());
}

TEST_F(SaveEdgeCases, SavingThroughASymbolicLinkWritesTheFileItPointsTo) {
    const Agent a = smallAgent();
    const Agent b = iotest::trainedAgent(iotest::mixedDescriptor(2), 50);
    fs::create_directories(dir_ / "store");
    const fs::path real = dir_ / "store" / "real.xml";
    saveAgent(a, real.string());
    fs::create_symlink("store/real.xml", dir_ / "link.xml");  // relative to the link's folder
    fs::create_symlink(dir_ / "link.xml", dir_ / "link-to-link.xml");

    saveAgent(b, (dir_ / "link.xml").string());
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.xml")) << "the save replaced the link";
    EXPECT_EQ(fileBytes(real), saveAgentToString(b));

    saveAgent(a, (dir_ / "link-to-link.xml").string());
    EXPECT_TRUE(fs::is_symlink(dir_ / "link-to-link.xml"));
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.xml"));
    EXPECT_EQ(fileBytes(real), saveAgentToString(a));

    fs::create_symlink(dir_ / "store" / "fresh.xml", dir_ / "dangling.xml");  // points at no file yet
    saveAgent(b, (dir_ / "dangling.xml").string());
    EXPECT_TRUE(fs::is_symlink(dir_ / "dangling.xml"));
    EXPECT_EQ(fileBytes(dir_ / "store" / "fresh.xml"), saveAgentToString(b));
    EXPECT_TRUE(leftovers().empty());

    fs::create_symlink("loop-b.xml", dir_ / "loop-a.xml");
    fs::create_symlink("loop-a.xml", dir_ / "loop-b.xml");
    EXPECT_NE(ioErrorOf([&] { saveAgent(a, (dir_ / "loop-a.xml").string()); }), "no error");
}

TEST_F(SaveEdgeCases, LoadingAFifoIsRefusedWithoutBlocking) {
    const fs::path fifo = dir_ / "agent.xml";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const int status = inChild([&] {
        const std::string message = ioErrorOf([&] { loadAgent(fifo.string()); });
        return message.find("not a regular file") != std::string::npos ? 0 : 1;
    });
    EXPECT_EQ(status, 0) << (status == -1 ? "loading a FIFO blocked" : "loading a FIFO was not refused as such");
}

TEST_F(SaveEdgeCases, LoadingADeviceIsRefused) {
    for (const char* device : {"/dev/zero", "/dev/null", "/dev/urandom"}) {
        const int status = inChild([&] {
            // If it reads /dev/zero, fail in the child, not the machine. Not under Address- or
            // ThreadSanitizer, whose shadow memory needs far more address space (the child's timeout
            // still holds).
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
            const rlimit memory{1u << 30, 1u << 30};
            ::setrlimit(RLIMIT_AS, &memory);
#endif
            const std::string message = ioErrorOf([&] { loadAgent(device); });
            return message.find("not a regular file") != std::string::npos ? 0 : 1;
        });
        EXPECT_EQ(status, 0) << device << (status == -1 ? ": the load did not return" : ": not refused as a device");
    }
}

TEST_F(SaveEdgeCases, AFileLargerThanTheLimitIsRefusedUnread) {
    const fs::path huge = dir_ / "huge.xml";
    { std::ofstream(huge) << "<verve"; }
    fs::resize_file(huge, io::kMaxSaveFileBytes + 1);  // sparse: no disk space used
    const std::string message = ioErrorOf([&] { loadAgent(huge.string()); });
    EXPECT_NE(message.find("1073741824-byte limit"), std::string::npos) << message;
}

TEST_F(SaveEdgeCases, AReadOnlyFolderIsAnIoErrorAndKeepsThePreviousSave) {
    const Agent small = smallAgent();
    const fs::path folder = dir_ / "read-only";
    fs::create_directories(folder);
    const fs::path target = folder / "agent.xml";
    saveAgent(small, target.string());
    const std::string before = fileBytes(target);
    fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
    const Agent other = iotest::trainedAgent(iotest::mixedDescriptor(2), 50);
    const int status = inChild([&] {
        // Root writes anywhere: the save runs as "nobody" then, for whom the folder is read-only.
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) return 2;
        return saveError(other, target) == ErrorCode::Io ? 0 : 1;
    });
    fs::permissions(folder, fs::perms::owner_all);
    EXPECT_EQ(status, 0) << "a save into a read-only folder did not fail with an Io error";
    EXPECT_EQ(fileBytes(target), before);
    for (const auto& e : fs::directory_iterator(folder)) EXPECT_EQ(e.path(), target);
}

TEST_F(SaveEdgeCases, AFullDiskIsAnIoErrorAndKeepsThePreviousSave) {
    const Agent small = smallAgent();
    const Agent medium = mediumAgent();
    const fs::path disk = dir_ / "disk";
    fs::create_directories(disk);
    enum { kPassed = 0, kNoTmpfs = 77 };
    // A 128 kB tmpfs in a private mount namespace of a child: it disappears with the child.
    const int status = inChild([&] {
        if (::unshare(CLONE_NEWNS) != 0 || ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0 ||
            ::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=128k") != 0) {
            return int{kNoTmpfs};
        }
        const std::string target = (disk / "agent.xml").string();
        saveAgent(small, target);
        const std::string before = fileBytes(target);
        if (saveError(medium, target) != ErrorCode::Io) return 1;  // ENOSPC
        if (fileBytes(target) != before) return 2;
        if (std::distance(fs::directory_iterator(disk), fs::directory_iterator()) != 1) return 3;  // a leftover
        return int{kPassed};
    });
    if (status == kNoTmpfs) GTEST_SKIP() << "cannot mount a tmpfs here (needs root); the RLIMIT_FSIZE test covers failed writes";
    EXPECT_EQ(status, kPassed) << "1: not an Io error, 2: the previous save changed, 3: a temporary file was left";
}

}  // namespace
}  // namespace verve
