#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace verve::demo {

Progress::Progress(std::uint32_t total, std::uint32_t linesWhenPiped)
    : total_(total),
      every_(std::max<std::uint32_t>(1, total / std::max<std::uint32_t>(1, linesWhenPiped))),
      tty_(isatty(fileno(stdout)) != 0),
      start_(std::chrono::steady_clock::now()) {}

double Progress::elapsedSeconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(std::uint32_t item, const std::string& text, bool force) {
    if (tty_) {
        std::printf("\r\033[K%u/%u %s  [%.1f s]", item, total_, text.c_str(), elapsedSeconds());
        open_ = true;
    } else if (force || item % every_ == 0 || item == total_) {
        std::printf("%u/%u %s  [%.1f s]\n", item, total_, text.c_str(), elapsedSeconds());
    }
    std::fflush(stdout);
}

void Progress::finish() {
    if (open_) std::printf("\n");
    open_ = false;
    std::fflush(stdout);
}

}  // namespace verve::demo
