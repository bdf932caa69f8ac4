// Save paths are UTF-8 on every platform: a folder and a file named outside ASCII save, replace
// and load through the C ABI (the Windows build converts them to UTF-16 for the wide file API).
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <string>
#include <thread>

#include "verve_c.h"

namespace {

// An agent with one continuous sensor and two actions (nullptr if it could not be made).
verve_agent* smallAgent() {
    verve_agent_desc desc;
    verve_agent_desc_default(&desc);
    desc.num_continuous_sensors = 1;
    desc.num_actions = 2;
    verve_agent* agent = nullptr;
    return verve_agent_create(&desc, &agent) == VERVE_OK ? agent : nullptr;
}

std::string memorySave(const verve_agent* agent) {
    size_t size = 0;
    EXPECT_EQ(verve_agent_save_memory(agent, nullptr, &size), VERVE_OK) << verve_last_error();
    std::string xml(size, '\0');
    EXPECT_EQ(verve_agent_save_memory(agent, &xml[0], &size), VERVE_OK) << verve_last_error();
    return xml;
}

TEST(CApiPaths, SaveAndLoadThroughANonAsciiPath) {
    verve_agent* agent = smallAgent();
    ASSERT_NE(agent, nullptr) << verve_last_error();
    for (int i = 0; i < 20; ++i) {
        const float sensor = static_cast<float>(i % 10) / 5.0f - 1.0f;
        uint32_t action = 0;
        ASSERT_EQ(verve_agent_update(agent, 0.5f, nullptr, 0, &sensor, 1, 0.1f, &action), VERVE_OK);
    }

    // "Grüße 目录" and "agent é.xml" in UTF-8.
    const std::string folder = ::testing::TempDir() + "verve Gr\xC3\xBC\xC3\x9F" "e \xE7\x9B\xAE\xE5\xBD\x95";
    const std::string path = folder + "/agent \xC3\xA9.xml";
    const std::filesystem::path native = std::filesystem::u8path(path);
    std::filesystem::remove_all(std::filesystem::u8path(folder));
    std::filesystem::create_directories(std::filesystem::u8path(folder));

    ASSERT_EQ(verve_agent_save(agent, path.c_str()), VERVE_OK) << verve_last_error();
    EXPECT_TRUE(std::filesystem::is_regular_file(native)) << "the file is not under its UTF-8 name";
    ASSERT_EQ(verve_agent_save(agent, path.c_str()), VERVE_OK) << "replacing it: " << verve_last_error();
    verve_agent* loaded = nullptr;
    ASSERT_EQ(verve_agent_load(path.c_str(), &loaded), VERVE_OK) << verve_last_error();
    EXPECT_EQ(memorySave(loaded), memorySave(agent));

    // Exactly one file: the atomic save's temporary files are gone.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(std::filesystem::u8path(folder)),
                            std::filesystem::directory_iterator()), 1);
    verve_agent_destroy(loaded);
    verve_agent_destroy(agent);
    std::filesystem::remove_all(std::filesystem::u8path(folder));
}

// Issue 32: a save while another thread loads the same file. On Windows a load opened the file
// without FILE_SHARE_DELETE, so a save meanwhile failed ("Access is denied"); the Windows build
// runs this under Wine, whose share modes are Windows'.
TEST(CApiPaths, SavesSucceedWhileAnotherThreadLoadsTheFile) {
    verve_agent* agent = smallAgent();
    ASSERT_NE(agent, nullptr) << verve_last_error();
    const std::string folder = ::testing::TempDir() + "verve_save_while_loading";
    const std::string path = folder + "/agent.xml";
    std::filesystem::remove_all(std::filesystem::u8path(folder));
    std::filesystem::create_directories(std::filesystem::u8path(folder));
    ASSERT_EQ(verve_agent_save(agent, path.c_str()), VERVE_OK) << verve_last_error();

    std::atomic<bool> done{false};
    std::atomic<int> loads{0}, loadFailures{0};
    std::thread loader([&] {
        while (!done) {
            verve_agent* loaded = nullptr;
            // A load may meet the file mid-replace on Windows (refused, never torn): counted only.
            if (verve_agent_load(path.c_str(), &loaded) == VERVE_OK) verve_agent_destroy(loaded);
            else ++loadFailures;
            ++loads;
        }
    });
    int failures = 0;
    std::string firstError;
    for (int i = 0; i < 150; ++i) {
        if (verve_agent_save(agent, path.c_str()) != VERVE_OK) {
            if (failures++ == 0) firstError = verve_last_error();
        }
    }
    done = true;
    loader.join();
    EXPECT_EQ(failures, 0) << "saves failed while the file was being loaded; the first: " << firstError;
    EXPECT_GT(loads.load(), 0);
    RecordProperty("loads", loads.load());
    RecordProperty("loadFailures", loadFailures.load());
    verve_agent_destroy(agent);
    std::filesystem::remove_all(std::filesystem::u8path(folder));
}

}  // namespace
