// Binary save -> AgentSnapshot: header, length and checksum first, then every count bounded by
// the bytes that remain before anything is allocated, then the same checks as an XML save.
#include <algorithm>
#include <cstring>
#include <type_traits>

#include "io/snapshot_binary.hpp"
#include "io/snapshot_binary_layout.hpp"
#include "io/snapshot_check.hpp"
#include "verve/error.hpp"

namespace verve::io {
namespace {

[[noreturn]] void fail(const std::string& message) { throw Error(ErrorCode::Format, message); }

// The fuzz preset defines this libFuzzer convention so that mutated inputs get past the checksum
// to the parser behind it; every other build checks the checksum.
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
constexpr bool kVerifyChecksum = false;
#else
constexpr bool kVerifyChecksum = true;
#endif

class Reader {
public:
    Reader(const char* data, std::size_t size) : at_(data), end_(data + size) {}

    std::size_t remaining() const { return static_cast<std::size_t>(end_ - at_); }

    void raw(const char* name, void* p, std::size_t n) {
        if (n > remaining()) {
            fail(std::string("binary save: '") + name + "' needs " + std::to_string(n) + " bytes, only " +
                 std::to_string(remaining()) + " remain (truncated or corrupt)");
        }
        if (n != 0) std::memcpy(p, at_, n);
        at_ += n;
    }
    template <typename T>
    void value(const char* name, T& v) {
        static_assert(std::is_arithmetic_v<T>);
        raw(name, &v, sizeof v);
    }
    void flag(const char* name, bool& b) {
        b = byte(name, 1) != 0;
    }
    template <typename E>
    void choice(const char* name, E& e, E max) {
        e = static_cast<E>(byte(name, static_cast<std::uint8_t>(max)));
    }
    template <typename T>
    void list(const char* name, std::vector<T>& v) {
        v.resize(count(name, sizeof(T)));
        raw(name, v.data(), v.size() * sizeof(T));
    }
    template <typename T, typename F>
    void items(const char* name, std::vector<T>& v, std::size_t itemBytes, F&& f) {
        v.resize(count(name, itemBytes));
        for (T& item : v) f(*this, item);
    }

private:
    std::uint8_t byte(const char* name, std::uint8_t max) {
        std::uint8_t b = 0;
        value(name, b);
        if (b > max) {
            fail(std::string("binary save: '") + name + "' is " + std::to_string(b) + ", at most " +
                 std::to_string(max) + " is valid");
        }
        return b;
    }
    // A count is refused unless its items fit in the bytes that remain: a hostile count can never
    // make the reader allocate more than the save's own size.
    std::size_t count(const char* name, std::size_t itemBytes) {
        std::uint64_t n = 0;
        value(name, n);
        if (n > remaining() / itemBytes) {
            fail(std::string("binary save: '") + name + "' declares " + std::to_string(n) + " items of " +
                 std::to_string(itemBytes) + " bytes, only " + std::to_string(remaining()) +
                 " bytes remain (truncated or corrupt)");
        }
        return static_cast<std::size_t>(n);
    }

    const char* at_;
    const char* end_;
};

}  // namespace

bool looksBinary(const char* data, std::size_t size) {
    return data != nullptr && size > 0 && std::memcmp(data, kBinaryMagic, std::min(size, sizeof kBinaryMagic)) == 0;
}

AgentSnapshot snapshotFromBinary(const char* data, std::size_t size) {
    if (data == nullptr) throw Error(ErrorCode::InvalidArgument, "no data (NULL pointer)");
    Reader header(data, size);
    char magic[sizeof kBinaryMagic];
    header.raw("magic", magic, sizeof magic);
    if (std::memcmp(magic, kBinaryMagic, sizeof magic) != 0) fail("not a Verve binary save (wrong magic bytes)");
    std::uint32_t version = 0;
    header.value("version", version);
    if (version == 0) fail("binary format version 0 is not a valid version");
    if (version > kBinaryFormatVersion) {
        throw Error(ErrorCode::Version, "the save has binary format version " + std::to_string(version) +
                                            "; this library reads up to version " +
                                            std::to_string(kBinaryFormatVersion) + " (update Verve)");
    }
    std::uint32_t reserved = 0;
    header.value("reserved", reserved);
    if (reserved != 0) fail("binary save: the reserved header field is " + std::to_string(reserved) + ", not 0");
    std::uint64_t payloadBytes = 0;
    std::uint64_t checksum = 0;
    header.value("payload_bytes", payloadBytes);
    header.value("checksum", checksum);
    if (payloadBytes != header.remaining()) {
        fail("binary save: the header announces " + std::to_string(payloadBytes) + " bytes of data, the save holds " +
             std::to_string(header.remaining()) + (payloadBytes > header.remaining() ? " (truncated?)" : ""));
    }
    const char* payload = data + kBinaryHeaderBytes;
    if (kVerifyChecksum && payloadChecksum(payload, header.remaining()) != checksum) {
        fail("binary save: checksum mismatch (the data is corrupt)");
    }

    Reader reader(payload, header.remaining());
    AgentSnapshot s;
    bool shortTerm = false;
    transferPayload(reader, s, shortTerm, version);
    if (reader.remaining() != 0) {
        fail("binary save: " + std::to_string(reader.remaining()) + " unexpected bytes after the data");
    }
    checkSnapshot(s);
    return s;
}

}  // namespace verve::io
