// guarded(): every exception becomes a result code plus a message, and nothing escapes.
#include <gtest/gtest.h>

#include <string>

#include "capi/capi_guard.hpp"

namespace verve::capi {
namespace {

TEST(Guard, MapsEachKindOfFailure) {
    EXPECT_EQ(guarded("f", [] {}), VERVE_OK);
    EXPECT_STREQ(verve_last_error(), "");

    EXPECT_EQ(guarded("f", [] { throw Error(ErrorCode::Version, "too new"); }), VERVE_ERROR_VERSION);
    EXPECT_STREQ(verve_last_error(), "f: too new");
    EXPECT_EQ(guarded("g", [] { throw std::bad_alloc(); }), VERVE_ERROR_OUT_OF_MEMORY);
    EXPECT_STREQ(verve_last_error(), "g: out of memory");
    EXPECT_EQ(guarded("h", [] { throw std::out_of_range("index 9"); }), VERVE_ERROR_INTERNAL);
    EXPECT_STREQ(verve_last_error(), "h: index 9");
    EXPECT_EQ(guarded("i", [] { throw 42; }), VERVE_ERROR_INTERNAL);
    EXPECT_STREQ(verve_last_error(), "i: unknown exception");
    EXPECT_EQ(guarded("j", [] {}), VERVE_OK);
    EXPECT_STREQ(verve_last_error(), "");
}

TEST(Guard, EveryErrorCodeHasItsResult) {
    EXPECT_EQ(toResult(ErrorCode::InvalidArgument), VERVE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(toResult(ErrorCode::InvalidState), VERVE_ERROR_INVALID_STATE);
    EXPECT_EQ(toResult(ErrorCode::Io), VERVE_ERROR_IO);
    EXPECT_EQ(toResult(ErrorCode::Format), VERVE_ERROR_FORMAT);
    EXPECT_EQ(toResult(ErrorCode::Version), VERVE_ERROR_VERSION);
    EXPECT_EQ(toResult(ErrorCode::OutOfMemory), VERVE_ERROR_OUT_OF_MEMORY);
    EXPECT_EQ(toResult(ErrorCode::BufferTooSmall), VERVE_ERROR_BUFFER_TOO_SMALL);
    EXPECT_EQ(toResult(ErrorCode::Internal), VERVE_ERROR_INTERNAL);
    EXPECT_EQ(toResult(static_cast<ErrorCode>(99)), VERVE_ERROR_INTERNAL);
}

TEST(Guard, LongMessagesAreTruncatedNotOverflowed) {
    const std::string huge(5000, 'x');
    EXPECT_EQ(guarded("f", [&] { throw Error(ErrorCode::Format, huge); }), VERVE_ERROR_FORMAT);
    const std::string message = verve_last_error();
    EXPECT_GT(message.size(), 500u);
    EXPECT_LT(message.size(), 1024u);
    EXPECT_EQ(message.rfind("f: xxx", 0), 0u);
}

}  // namespace
}  // namespace verve::capi
