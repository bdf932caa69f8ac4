// Recorded demonstrations (docs/teaching.md, "Recordings"): the steps a player or a scripted AI
// took, kept in memory or in a file (checksummed, versioned, bounded like a save), and replayed
// into an agent as demonstrated steps to train it before it ships.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "verve/agent.hpp"
#include "verve/agent_descriptor.hpp"
#include "verve/observation.hpp"

namespace verve {

class Recording {
public:
    // ContinuousStep: a Step that also holds the teacher's continuous actions (addStep with them).
    enum class Kind : std::uint8_t { Step = 0, EndEpisode = 1, Truncation = 2, ContinuousStep = 3 };
    // At most this many entries (steps and trial ends), 310 hours at 60 steps a second; a larger
    // file is refused before anything is allocated for it.
    static constexpr std::uint64_t kMaxEntries = std::uint64_t{1} << 26;

    // A recording for agents with these sensors (value counts of the discrete ones, the number of
    // continuous ones) and actions (and continuous actions, for steps that carry them); every entry
    // is checked against them as it is added.
    Recording(std::vector<std::uint32_t> discreteSensors, std::uint32_t continuousSensors, std::uint32_t numActions,
              std::uint32_t continuousActions = 0);
    static Recording shapedLike(const AgentDescriptor& desc);

    // As Agent::updateDemonstrated, Agent::endEpisode and Agent::truncateEpisode take them. Each
    // throws Error(InvalidArgument) and records nothing when a value is out of range, not finite,
    // or the sizes do not match; Error(InvalidState) beyond kMaxEntries.
    void addStep(float reward, ObservationView obs, float dt, std::uint32_t action);
    // With the teacher's continuous actions, as Agent::updateDemonstrated takes them (the count must
    // be continuousActions(); each value within [-1, 1]).
    void addStep(float reward, ObservationView obs, float dt, std::uint32_t action, ContinuousActionView continuousAction);
    void addEndEpisode(float finalReward);
    void addTruncation(float reward);

    // Every entry into `agent` in order, as demonstrated steps and trial ends. The agent's sensors
    // and actions must be the recording's, and its continuous actions too when a step holds
    // them (else Error(InvalidArgument), nothing replayed). Every
    // entry was checked when it was added or loaded, so only running out of memory can stop a
    // replay part-way: the agent then keeps the entries before it (each is all or nothing).
    void replayInto(Agent& agent) const;

    std::size_t size() const { return kinds_.size(); }
    std::size_t steps() const { return actions_.size(); }
    const std::vector<std::uint32_t>& discreteSensors() const { return shape_.discreteSensors; }
    std::uint32_t continuousSensors() const { return static_cast<std::uint32_t>(shape_.continuousSensors.size()); }
    std::uint32_t numActions() const { return shape_.numActions; }
    std::uint32_t continuousActions() const { return shape_.continuousActions; }

    // The parts, for the file format (src/io/recording_binary.cpp): entry i has kinds()[i] and
    // rewards()[i]; the j-th Step (of either kind) has dts()[j], actions()[j] and its sensors at j *
    // their counts; the k-th ContinuousStep its continuous actions at k * continuousActions().
    const std::vector<Kind>& kinds() const { return kinds_; }
    const std::vector<float>& rewards() const { return rewards_; }
    const std::vector<float>& dts() const { return dts_; }
    const std::vector<std::uint32_t>& actions() const { return actions_; }
    const std::vector<std::int32_t>& discreteValues() const { return discrete_; }
    const std::vector<float>& continuousValues() const { return continuous_; }
    const std::vector<float>& continuousActionValues() const { return continuousActions_; }

private:
    void checkRoom() const;
    // Either step; `continuousAction` checked already (nullptr: a plain Step).
    void addChecked(float reward, ObservationView obs, float dt, std::uint32_t action, const ContinuousActionView* continuousAction);
    void addEnd(Kind kind, float reward, const char* what);  // a trial's end of either kind
    AgentDescriptor shape_;  // the sensors and actions; nothing else is used
    std::vector<Kind> kinds_;
    std::vector<float> rewards_;
    std::vector<float> dts_;
    std::vector<std::uint32_t> actions_;
    std::vector<std::int32_t> discrete_;
    std::vector<float> continuous_;
    std::vector<float> continuousActions_;
};

// The file (docs/teaching.md, "Recordings"): little-endian, "VERVEREC" | u32 version | u32 0 |
// u64 payload bytes | u64 checksum, then the shape and the entries. Saves are atomic as agents'
// are. Loading throws Error(Io) when the file cannot be read, Error(Format) naming what is wrong
// for a corrupt or truncated one, Error(Version) for a newer format.
std::string recordingToBytes(const Recording& recording);
Recording recordingFromBytes(const char* data, std::size_t size);
void saveRecording(const Recording& recording, const std::string& path);
Recording loadRecording(const std::string& path);

}  // namespace verve
