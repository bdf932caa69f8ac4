// A fresh scratch directory per test, for the tests that save to real files (POSIX).
#pragma once
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "io_test_support.hpp"
#include "verve/io.hpp"

namespace verve::iotest {

inline std::string fileBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

class SaveDir : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::temp_directory_path() /
               ("verve_" + std::string(test->name()) + "_" + std::to_string(::getpid()));
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    // Temporary files of saves, wherever they came from.
    std::vector<std::string> leftovers() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(dir_)) {
            if (e.path().filename().string().find(".tmp-") != std::string::npos) names.push_back(e.path().string());
        }
        return names;
    }

    // The error code of a save or load that must fail ("no error" is reported as Internal).
    template <typename F>
    static ErrorCode errorOf(F&& call) {
        try {
            call();
        } catch (const Error& e) {
            return e.code();
        }
        return ErrorCode::Internal;
    }
    static ErrorCode saveError(const Agent& agent, const std::filesystem::path& path) {
        return errorOf([&] { saveAgent(agent, path.string()); });
    }
    // How many of `count` saves of `agent` to `path` failed.
    static int failedSaves(const Agent& agent, const std::filesystem::path& path, int count) {
        int failures = 0;
        for (int i = 0; i < count; ++i) failures += saveError(agent, path) == ErrorCode::Internal ? 0 : 1;
        return failures;
    }

    // Runs `body` in a child process (its return value is the exit status) and waits at most
    // `limit` for it; a child still running then is killed and reported as -1, so a call that
    // blocks fails the test instead of hanging it.
    template <typename F>
    static int inChild(F&& body, std::chrono::milliseconds limit = std::chrono::seconds(20)) {
        const pid_t child = ::fork();
        if (child == 0) ::_exit(body());
        const auto deadline = std::chrono::steady_clock::now() + limit;
        int status = 0;
        while (::waitpid(child, &status, WNOHANG) == 0) {
            if (std::chrono::steady_clock::now() > deadline) {
                ::kill(child, SIGKILL);
                ::waitpid(child, &status, 0);
                return -1;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        return WIFEXITED(status) ? WEXITSTATUS(status) : -2;
    }

    std::filesystem::path dir_;
};

}  // namespace verve::iotest
