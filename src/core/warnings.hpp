// Warnings for the host: the call succeeded, but something deserves attention (a clamped
// reward, an RBF budget reached). The core never prints: a sink installed by the C ABI forwards
// them to the host's log hook. Formatting uses a fixed buffer, so warning never allocates.
#pragma once

namespace verve::core {

using WarningSink = void (*)(const char* message) noexcept;

void setWarningSink(WarningSink sink) noexcept;
void warn(const char* format, ...) noexcept __attribute__((format(printf, 1, 2)));

}  // namespace verve::core
