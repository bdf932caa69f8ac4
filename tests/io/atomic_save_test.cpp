// Saves to a path are atomic: killing a saving process at any moment leaves a loadable save,
// and a failed save leaves neither a changed target nor a temporary file.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <thread>

#include "io_test_support.hpp"
#include "verve/io.hpp"

namespace fs = std::filesystem;

namespace verve {
namespace {

class AtomicSave : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("verve_atomic_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::vector<std::string> leftovers() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir_)) {
            if (e.path().filename().string().find(".tmp-") != std::string::npos) names.push_back(e.path().string());
        }
        return names;
    }

    static ErrorCode saveError(const Agent& agent, const fs::path& path) {
        try {
            saveAgent(agent, path.string());
        } catch (const Error& e) {
            return e.code();
        }
        return ErrorCode::Internal;  // "no error" is wrong too
    }

    fs::path dir_;
};

// A big agent: the full lattice of 2 sensors at resolution 90 (8100 RBFs), about 400 kB of XML.
Agent bigAgent(std::uint64_t feedSeed) {
    AgentDescriptor d;
    d.addContinuousSensor().addContinuousSensor();
    d.resolution = 90;
    d.numActions = 4;
    d.allocation = RbfAllocation::Full;
    return iotest::trainedAgent(d, 300, feedSeed);
}

TEST_F(AtomicSave, KilledMidSaveTheTargetAlwaysLoads) {
    const Agent a = bigAgent(1);
    const Agent b = bigAgent(2);
    ASSERT_FALSE(iotest::sameBits(a.snapshot().weights, b.snapshot().weights));
    const fs::path target = dir_ / "agent.xml";
    saveAgent(a, target.string());

    std::mt19937 rng(42);
    int killedMidWrite = 0;
    for (int round = 0; round < 25; ++round) {
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {  // saves forever, alternating two different agents
            try {
                for (unsigned i = 0;; ++i) saveAgent(i % 2 ? a : b, target.string());
            } catch (...) {
            }
            ::_exit(1);
        }
        std::this_thread::sleep_for(std::chrono::microseconds(2000 + rng() % 40000));
        ::kill(child, SIGKILL);
        int status = 0;
        ::waitpid(child, &status, 0);
        ASSERT_TRUE(WIFSIGNALED(status)) << "the saving child stopped on its own (status " << status << ")";

        const Agent loaded = loadAgent(target.string());  // throws if the save is torn
        const auto w = loaded.snapshot().weights;
        EXPECT_TRUE(iotest::sameBits(w, a.snapshot().weights) || iotest::sameBits(w, b.snapshot().weights));
        // A kill leaves the child's temporary file behind (nothing can clean up after SIGKILL).
        const auto temps = leftovers();
        killedMidWrite += static_cast<int>(temps.size());
        for (const auto& t : temps) fs::remove(t);
    }
    // The kills must actually land inside saves, or the test proves nothing.
    EXPECT_GT(killedMidWrite, 2);
    std::printf("[          ] %d of 25 kills landed while a temporary file existed\n", killedMidWrite);
}

TEST_F(AtomicSave, AFailedRenameLeavesNoTemporaryFile) {
    const Agent agent = iotest::trainedAgent(iotest::mixedDescriptor(), 50);
    const fs::path target = dir_ / "occupied";
    fs::create_directories(target / "child");  // a non-empty directory cannot be renamed over
    EXPECT_EQ(saveError(agent, target), ErrorCode::Io);
    EXPECT_TRUE(leftovers().empty());
    EXPECT_TRUE(fs::is_directory(target / "child"));
}

TEST_F(AtomicSave, AMissingDirectoryIsAnIoError) {
    const Agent agent = iotest::trainedAgent(iotest::mixedDescriptor(), 50);
    EXPECT_EQ(saveError(agent, dir_ / "no" / "such" / "dir" / "agent.xml"), ErrorCode::Io);
    EXPECT_EQ(saveError(agent, ""), ErrorCode::InvalidArgument);
}

TEST_F(AtomicSave, AFailedWriteKeepsThePreviousSave) {
    const Agent small = iotest::trainedAgent(iotest::mixedDescriptor(1), 50);
    const fs::path target = dir_ / "agent.xml";
    saveAgent(small, target.string());
    const std::string before = saveAgentToString(small);
    const Agent big = bigAgent(3);

    // In a child whose file-size limit is far below the big save, write() fails (EFBIG).
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{64 * 1024, 64 * 1024};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        ::_exit(saveError(big, target) == ErrorCode::Io ? 0 : 1);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "the oversized save did not fail with an Io error";
    EXPECT_TRUE(leftovers().empty());
    EXPECT_EQ(saveAgentToString(loadAgent(target.string())), before);
}

TEST_F(AtomicSave, LoadErrorsNameTheFile) {
    try {
        loadAgent((dir_ / "missing.xml").string());
        FAIL() << "loaded a missing file";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ErrorCode::Io);
        EXPECT_NE(std::string(e.what()).find("missing.xml"), std::string::npos) << e.what();
    }
    try {
        loadAgent(dir_.string());  // a directory
        FAIL() << "loaded a directory";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ErrorCode::Io) << e.what();
    }
}

}  // namespace
}  // namespace verve
