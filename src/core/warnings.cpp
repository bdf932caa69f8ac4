#include "core/warnings.hpp"

#include <atomic>
#include <cstdarg>
#include <cstdio>

namespace verve::core {
namespace {

std::atomic<WarningSink> sink{nullptr};

}  // namespace

void setWarningSink(WarningSink s) noexcept { sink.store(s, std::memory_order_release); }

void warn(const char* format, ...) noexcept {
    const WarningSink s = sink.load(std::memory_order_acquire);
    if (s == nullptr) return;
    char message[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(message, sizeof message, format, args);
    va_end(args);
    s(message);
}

}  // namespace verve::core
