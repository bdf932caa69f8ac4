// Saves to a path are atomic: killing a saving process at any moment leaves a loadable save, the
// temporary files of killed saves do not accumulate, and a failed save leaves neither a changed
// target nor a temporary file.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <thread>

#include "io/atomic_file.hpp"
#include "io_test_support.hpp"
#include "save_dir_fixture.hpp"
#include "verve/io.hpp"

namespace fs = std::filesystem;

namespace verve {
namespace {

using AtomicSave = iotest::SaveDir;
using iotest::fileBytes;

// A big agent: the full lattice of 3 sensors at resolution 40 (64,000 RBFs), about 8 MB of XML.
Agent bigAgent(std::uint64_t feedSeed) {
    AgentDescriptor d;
    d.addContinuousSensor().addContinuousSensor().addContinuousSensor();
    d.resolution = 40;
    d.numActions = 4;
    d.allocation = RbfAllocation::Full;
    return iotest::trainedAgent(d, 300, feedSeed);
}

TEST_F(AtomicSave, KilledMidSaveTheTargetAlwaysLoads) {
    const Agent a = bigAgent(1);
    const Agent b = bigAgent(2);
    const std::string xmlA = saveAgentToString(a);
    const std::string xmlB = saveAgentToString(b);
    ASSERT_NE(xmlA, xmlB);
    const fs::path target = dir_ / "agent.xml";
    saveAgent(a, target.string());

    const auto start = std::chrono::steady_clock::now();
    std::mt19937 rng(42);
    int killedMidWrite = 0;
    constexpr int kKills = 100;
    for (int round = 0; round < kKills; ++round) {
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {  // saves forever, alternating two different agents
            try {  // the file part of saveAgent: serialising would take most of the time otherwise
                for (unsigned i = 0;; ++i) io::writeFileAtomically(target.string(), i % 2 ? xmlB : xmlA);
            } catch (...) {
            }
            ::_exit(1);
        }
        std::this_thread::sleep_for(std::chrono::microseconds(1000 + rng() % 60000));
        ::kill(child, SIGKILL);
        int status = 0;
        ::waitpid(child, &status, 0);
        ASSERT_TRUE(WIFSIGNALED(status)) << "the saving child stopped on its own (status " << status << ")";

        const std::string bytes = fileBytes(target);  // exactly one of the two saves, never a mix
        ASSERT_TRUE(bytes == xmlA || bytes == xmlB) << "round " << round << ": a torn save of " << bytes.size() << " bytes";
        // Each save removes what killed saves left, so at most the last kill's file is there.
        const auto temps = leftovers();
        ASSERT_LE(temps.size(), 1u) << "temporary files accumulate: " << temps.size() << " after round " << round;
        killedMidWrite += static_cast<int>(temps.size());
    }
    saveAgent(a, target.string());
    EXPECT_TRUE(leftovers().empty()) << "a save left a killed save's temporary file in place";
    iotest::expectSameSnapshot(loadAgent(target.string()).snapshot(), a.snapshot());
    // The kills must actually land inside saves, or the test proves nothing.
    EXPECT_GT(killedMidWrite, kKills / 10);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[          ] %d of %d kills landed while a temporary file existed (%zu-byte saves, %.1f s)\n",
                killedMidWrite, kKills, xmlA.size(), seconds);
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
    const int status = inChild([&] {
        ::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{64 * 1024, 64 * 1024};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        return saveError(big, target) == ErrorCode::Io ? 0 : 1;
    });
    EXPECT_EQ(status, 0) << "the oversized save did not fail with an Io error";
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
