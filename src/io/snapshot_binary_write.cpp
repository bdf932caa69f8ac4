// AgentSnapshot -> binary save (layout in snapshot_binary.hpp and snapshot_binary_layout.hpp).
#include <cstring>
#include <type_traits>

#include "io/snapshot_binary.hpp"
#include "io/snapshot_binary_layout.hpp"
#include "io/snapshot_check.hpp"
#include "verve/error.hpp"

// The format is little-endian and values are copied as they are in memory.
#if defined(__BYTE_ORDER__)
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the binary save format assumes a little-endian host");
#endif

namespace verve::io {
namespace {

// Counts the payload's bytes, so the writer allocates the save once.
struct Sizer {
    std::size_t bytes = 0;
    template <typename T>
    void value(const char*, const T&) { bytes += sizeof(T); }
    void flag(const char*, const bool&) { bytes += 1; }
    template <typename E>
    void choice(const char*, const E&, E) { bytes += 1; }
    template <typename T>
    void list(const char*, const std::vector<T>& v) { bytes += 8 + v.size() * sizeof(T); }
    template <typename T, typename F>
    void items(const char*, const std::vector<T>& v, std::size_t, F&& f) {
        bytes += 8;
        for (const T& item : v) f(*this, item);
    }
};

struct Writer {
    char* at;
    void raw(const void* p, std::size_t n) {
        if (n != 0) std::memcpy(at, p, n);
        at += n;
    }
    template <typename T>
    void value(const char*, const T& v) {
        static_assert(std::is_arithmetic_v<T>);
        raw(&v, sizeof v);
    }
    void flag(const char*, const bool& b) { *at++ = b ? 1 : 0; }
    template <typename E>
    void choice(const char*, const E& e, E) { *at++ = static_cast<char>(e); }
    template <typename T>
    void list(const char*, const std::vector<T>& v) {
        value("count", std::uint64_t{v.size()});
        raw(v.data(), v.size() * sizeof(T));
    }
    template <typename T, typename F>
    void items(const char*, const std::vector<T>& v, std::size_t, F&& f) {
        value("count", std::uint64_t{v.size()});
        for (const T& item : v) f(*this, item);
    }
};

std::uint64_t mix(std::uint64_t h) {  // the final avalanche of splitmix64
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ULL;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBULL;
    return h ^ (h >> 31);
}

}  // namespace

std::uint64_t payloadChecksum(const char* data, std::size_t size) {
    constexpr std::uint64_t kOdd = 0x9E3779B97F4A7C15ULL;
    std::uint64_t h = 0x243F6A8885A308D3ULL;
    std::size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        std::uint64_t word;
        std::memcpy(&word, data + i, 8);
        h = ((h ^ word) * kOdd);  // xor then multiplication by an odd number: both bijections
        h = (h << 29) | (h >> 35);
    }
    std::uint64_t tail = 0;
    std::memcpy(&tail, data + i, size - i);
    h = ((h ^ tail) * kOdd);
    return mix(h ^ size);
}

std::string snapshotToBinary(const AgentSnapshot& snapshot, bool includeTraces) {
    try {
        checkSnapshot(snapshot);
    } catch (const Error& e) {
        throw Error(ErrorCode::Internal, std::string("refusing to save an inconsistent agent: ") + e.what());
    }
    const bool shortTerm = includeTraces;
    Sizer sizer;
    transferPayload(sizer, snapshot, shortTerm, kBinaryFormatVersion);
    std::string out(kBinaryHeaderBytes + sizer.bytes, '\0');
    Writer payload{out.data() + kBinaryHeaderBytes};
    transferPayload(payload, snapshot, shortTerm, kBinaryFormatVersion);

    Writer header{out.data()};
    header.raw(kBinaryMagic, sizeof kBinaryMagic);
    header.value("version", kBinaryFormatVersion);
    header.value("reserved", std::uint32_t{0});
    header.value("payload_bytes", std::uint64_t{sizer.bytes});
    header.value("checksum", payloadChecksum(out.data() + kBinaryHeaderBytes, sizer.bytes));
    return out;
}

}  // namespace verve::io
