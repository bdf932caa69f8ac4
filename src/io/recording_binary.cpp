// verve::Recording <-> its file (docs/teaching.md, "Recordings"). Little-endian, no padding:
//
//   header  : magic "VERVEREC" | u32 format version | u32 0 | u64 payload bytes | u64 checksum
//             of the payload (io::payloadChecksum, as binary saves)
//   payload : u32 actions | u32 discrete sensors, then u32 values of each | u32 continuous sensors |
//             [v2: u32 continuous actions] | u64 entries | u64 steps | [v2: u64 continuous steps] |
//             u8 kind per entry (0 step, 1 end of trial, 2 truncation, 3 step with continuous
//             actions, v2) | f32 reward per entry | f32 dt per step (either kind) | u32 action per
//             step | i32 discrete values per step | f32 continuous values per step |
//             [v2: f32 continuous actions per kind-3 step]
//
// Version 2 added the teacher's continuous actions; version 1 files load as recordings without them.
// Loading checks the header, the checksum and that the counts add up to the payload's size
// exactly before allocating anything, then adds every entry through Recording's own checks.
#include <cstring>
#include <string>

#include "io/atomic_file.hpp"
#include "io/snapshot_binary.hpp"
#include "verve/error.hpp"
#include "verve/recording.hpp"

#if defined(__BYTE_ORDER__)
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the recording format assumes a little-endian host");
#endif

namespace verve {
namespace {

constexpr char kMagic[8] = {'V', 'E', 'R', 'V', 'E', 'R', 'E', 'C'};
constexpr std::uint32_t kVersion = 2;
constexpr std::size_t kHeaderBytes = 32;

#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
constexpr bool kVerifyChecksum = false;  // mutated inputs reach the parser (as binary saves)
#else
constexpr bool kVerifyChecksum = true;
#endif

[[noreturn]] void fail(const std::string& message) { throw Error(ErrorCode::Format, "recording: " + message); }

template <typename T>
void put(std::string& out, const T& v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
}
template <typename T>
void putAll(std::string& out, const std::vector<T>& v) {
    if (!v.empty()) out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

class Reader {
public:
    Reader(const char* data, std::size_t size) : at_(data), end_(data + size) {}
    template <typename T>
    T take(const char* what) {
        T v;
        if (static_cast<std::size_t>(end_ - at_) < sizeof v) fail(std::string("truncated at ") + what);
        std::memcpy(&v, at_, sizeof v);
        at_ += sizeof v;
        return v;
    }
    const char* skip(std::size_t bytes) {
        const char* start = at_;
        at_ += bytes;  // the caller checked the size
        return start;
    }
    std::size_t remaining() const { return static_cast<std::size_t>(end_ - at_); }

private:
    const char* at_;
    const char* end_;
};

template <typename T>
T at(const char* base, std::size_t i) {
    T v;
    std::memcpy(&v, base + i * sizeof v, sizeof v);
    return v;
}

}  // namespace

std::string recordingToBytes(const Recording& r) {
    std::string payload;
    put(payload, r.numActions());
    put(payload, static_cast<std::uint32_t>(r.discreteSensors().size()));
    for (std::uint32_t values : r.discreteSensors()) put(payload, values);
    put(payload, r.continuousSensors());
    put(payload, r.continuousActions());
    put(payload, std::uint64_t{r.size()});
    put(payload, std::uint64_t{r.steps()});
    const std::uint64_t continuousSteps = r.continuousActions() ? r.continuousActionValues().size() / r.continuousActions() : 0;
    put(payload, continuousSteps);
    for (Recording::Kind k : r.kinds()) put(payload, static_cast<std::uint8_t>(k));
    putAll(payload, r.rewards());
    putAll(payload, r.dts());
    putAll(payload, r.actions());
    putAll(payload, r.discreteValues());
    putAll(payload, r.continuousValues());
    putAll(payload, r.continuousActionValues());
    std::string out(kMagic, sizeof kMagic);
    put(out, kVersion);
    put(out, std::uint32_t{0});
    put(out, std::uint64_t{payload.size()});
    put(out, io::payloadChecksum(payload.data(), payload.size()));
    return out + payload;
}

Recording recordingFromBytes(const char* data, std::size_t size) {
    if (data == nullptr && size != 0) fail("no data");
    Reader header(data, size);
    if (size < sizeof kMagic || std::memcmp(data, kMagic, sizeof kMagic) != 0) fail("not a Verve recording (no VERVEREC magic)");
    header.skip(sizeof kMagic);
    const auto version = header.take<std::uint32_t>("the version");
    if (version > kVersion) {
        throw Error(ErrorCode::Version, "the recording has format version " + std::to_string(version) +
                                            ", this library reads up to " + std::to_string(kVersion) + " (update Verve)");
    }
    if (version == 0 || header.take<std::uint32_t>("the header") != 0) fail("bad header");
    const auto payloadBytes = header.take<std::uint64_t>("the payload size");
    const auto checksum = header.take<std::uint64_t>("the checksum");
    if (payloadBytes != header.remaining()) {
        fail("the header says " + std::to_string(payloadBytes) + " payload bytes, the data has " + std::to_string(header.remaining()));
    }
    const char* payload = data + kHeaderBytes;
    if (kVerifyChecksum && io::payloadChecksum(payload, payloadBytes) != checksum) fail("checksum mismatch (the file is damaged)");

    Reader in(payload, payloadBytes);
    const auto actions = in.take<std::uint32_t>("the actions");
    const auto nd = in.take<std::uint32_t>("the discrete sensors");
    if (nd > DescriptorLimits::kMaxSensors) fail(std::to_string(nd) + " discrete sensors");
    std::vector<std::uint32_t> discreteSensors(nd);
    for (auto& values : discreteSensors) values = in.take<std::uint32_t>("a discrete sensor");
    const auto nc = in.take<std::uint32_t>("the continuous sensors");
    const auto nca = version >= 2 ? in.take<std::uint32_t>("the continuous actions") : 0u;
    if (nca > DescriptorLimits::kMaxContinuousActions) fail(std::to_string(nca) + " continuous actions");
    const auto entries = in.take<std::uint64_t>("the entry count");
    const auto steps = in.take<std::uint64_t>("the step count");
    const auto continuousSteps = version >= 2 ? in.take<std::uint64_t>("the continuous step count") : 0u;
    if (entries > Recording::kMaxEntries || steps > entries || continuousSteps > steps) fail("bad entry or step count");
    if (nc > DescriptorLimits::kMaxSensors) fail(std::to_string(nc) + " continuous sensors");
    // Every count bounded above: the product fits 64 bits, and must be the bytes left, exactly.
    const std::uint64_t expected = entries * 5 + steps * (8 + 4 * (std::uint64_t{nd} + nc)) + continuousSteps * 4 * nca;
    if (expected != in.remaining()) {
        fail(std::to_string(entries) + " entries and " + std::to_string(steps) + " steps need " + std::to_string(expected) +
             " bytes, the payload has " + std::to_string(in.remaining()));
    }
    Recording r = [&] {
        try {
            return Recording(std::move(discreteSensors), nc, actions, nca);
        } catch (const Error& e) {
            fail(e.what());
        }
    }();
    const char* kinds = in.skip(entries);
    const char* rewards = in.skip(entries * 4);
    const char* dts = in.skip(steps * 4);
    const char* acts = in.skip(steps * 4);
    const char* discrete = in.skip(steps * nd * 4);
    const char* continuous = in.skip(steps * nc * 4);
    const char* continuousActions = in.skip(continuousSteps * nca * 4);
    std::vector<std::int32_t> d(nd);
    std::vector<float> c(nc);
    std::vector<float> ca(nca);
    std::uint64_t step = 0, continuousStep = 0;
    for (std::uint64_t i = 0; i < entries; ++i) {
        const auto kind = static_cast<std::uint8_t>(kinds[i]);
        const float reward = at<float>(rewards, i);
        try {
            if (kind == 1) {
                r.addEndEpisode(reward);
            } else if (kind == 2) {
                r.addTruncation(reward);
            } else if ((kind == 0 || (kind == 3 && nca > 0 && continuousStep < continuousSteps)) && step < steps) {
                for (std::uint32_t k = 0; k < nd; ++k) d[k] = at<std::int32_t>(discrete, step * nd + k);
                for (std::uint32_t k = 0; k < nc; ++k) c[k] = at<float>(continuous, step * nc + k);
                const ObservationView obs{d.data(), nd, c.data(), nc};
                if (kind == 3) {
                    for (std::uint32_t k = 0; k < nca; ++k) ca[k] = at<float>(continuousActions, continuousStep * nca + k);
                    r.addStep(reward, obs, at<float>(dts, step), at<std::uint32_t>(acts, step), ContinuousActionView{ca.data(), nca});
                    ++continuousStep;
                } else {
                    r.addStep(reward, obs, at<float>(dts, step), at<std::uint32_t>(acts, step));
                }
                ++step;
            } else {
                fail("entry " + std::to_string(i) + " has kind " + std::to_string(kind) + " (or more steps than counted)");
            }
        } catch (const Error& e) {
            if (e.code() != ErrorCode::InvalidArgument) throw;
            fail("entry " + std::to_string(i) + ": " + e.what());
        }
    }
    if (step != steps) fail(std::to_string(steps) + " steps counted, " + std::to_string(step) + " found");
    if (continuousStep != continuousSteps) {
        fail(std::to_string(continuousSteps) + " steps with continuous actions counted, " + std::to_string(continuousStep) + " found");
    }
    return r;
}

void saveRecording(const Recording& recording, const std::string& path) {
    io::writeFileAtomically(path, recordingToBytes(recording));
}

Recording loadRecording(const std::string& path) {
    const std::string bytes = io::readWholeFile(path);
    return recordingFromBytes(bytes.data(), bytes.size());
}

}  // namespace verve
