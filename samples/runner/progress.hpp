// One progress line: rewritten in place on a terminal, plain lines (fewer of them) otherwise,
// so logs and CI output stay readable.
#pragma once
#include <chrono>
#include <cstdint>
#include <string>

namespace verve::demo {

class Progress {
public:
    // `linesWhenPiped`: about how many plain lines a run of `total` items prints when not a tty.
    Progress(std::uint32_t total, std::uint32_t linesWhenPiped = 20);
    // `item` is 1-based; `text` is what to show after the counter. `force` prints even between
    // the piped lines (a run's last item, a new record).
    void update(std::uint32_t item, const std::string& text, bool force = false);
    void finish();  // ends the in-place line on a terminal
    double elapsedSeconds() const;

private:
    std::uint32_t total_;
    std::uint32_t every_;
    bool tty_;
    bool open_ = false;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace verve::demo
