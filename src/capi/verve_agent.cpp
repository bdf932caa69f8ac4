// Agent life cycle and stepping.
#include <string>

#include "capi/capi_agent.hpp"
#include "capi/capi_desc.hpp"

using verve::capi::AgentUse;
using verve::capi::guarded;
using verve::capi::requireArg;

extern "C" {

VERVE_API void VERVE_CALL verve_agent_desc_default(verve_agent_desc* desc) {
    if (desc != nullptr) *desc = verve::capi::defaultDesc();
}

VERVE_API verve_result VERVE_CALL verve_agent_desc_init(verve_agent_desc* desc, uint32_t struct_size) {
    return guarded(__func__, [&] {
        requireArg(desc, "desc");
        verve::capi::initDesc(*desc, struct_size);
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_create(const verve_agent_desc* desc, verve_agent** out) {
    return guarded(__func__, [&] {
        requireArg(desc, "desc");
        requireArg(out, "out");
        verve::capi::handOut(verve::Agent(verve::capi::toDescriptor(*desc)), out);
    });
}

VERVE_API void VERVE_CALL verve_agent_destroy(verve_agent* agent) {
    if (agent == nullptr) return;
    // Freeing an agent another thread is inside would crash that thread: it stays alive instead.
    if (!verve::capi::tryAcquire(agent->inUse)) {
        verve::capi::recordError(__func__, VERVE_ERROR_INVALID_STATE, "the agent is in use by another call: not destroyed");
        return;
    }
    delete agent;
}

VERVE_API verve_result VERVE_CALL verve_agent_update(verve_agent* agent, float reward, const int32_t* discrete,
                                                     uint32_t n_discrete, const float* continuous,
                                                     uint32_t n_continuous, float dt, uint32_t* out_action) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        verve::Agent& a = use.agent();
        requireArg(out_action, "out_action");
        if (n_discrete > 0) requireArg(discrete, "discrete (with n_discrete > 0)");
        if (n_continuous > 0) requireArg(continuous, "continuous (with n_continuous > 0)");
        *out_action = a.update(reward, verve::ObservationView{discrete, n_discrete, continuous, n_continuous}, dt);
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_update_masked(verve_agent* agent, float reward, const int32_t* discrete,
                                                            uint32_t n_discrete, const float* continuous,
                                                            uint32_t n_continuous, float dt, const uint8_t* action_mask,
                                                            uint32_t n_actions, uint32_t* out_action) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        verve::Agent& a = use.agent();
        requireArg(out_action, "out_action");
        requireArg(action_mask, "action_mask");
        if (n_discrete > 0) requireArg(discrete, "discrete (with n_discrete > 0)");
        if (n_continuous > 0) requireArg(continuous, "continuous (with n_continuous > 0)");
        *out_action = a.update(reward, verve::ObservationView{discrete, n_discrete, continuous, n_continuous}, dt,
                               verve::ActionMask{action_mask, n_actions});
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_update_demonstrated(verve_agent* agent, float reward,
                                                                  const int32_t* discrete, uint32_t n_discrete,
                                                                  const float* continuous, uint32_t n_continuous,
                                                                  float dt, const uint8_t* action_mask,
                                                                  uint32_t n_actions, uint32_t action) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        if (n_discrete > 0) requireArg(discrete, "discrete (with n_discrete > 0)");
        if (n_continuous > 0) requireArg(continuous, "continuous (with n_continuous > 0)");
        if (action_mask == nullptr && n_actions != 0) requireArg(action_mask, "action_mask (with n_actions > 0)");
        use.agent().updateDemonstrated(reward, verve::ObservationView{discrete, n_discrete, continuous, n_continuous},
                                       dt, action, verve::ActionMask{action_mask, n_actions});
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_update_demonstrated_continuous(
    verve_agent* agent, float reward, const int32_t* discrete, uint32_t n_discrete, const float* continuous,
    uint32_t n_continuous, float dt, const uint8_t* action_mask, uint32_t n_actions, uint32_t action,
    const float* continuous_action, uint32_t n_continuous_actions) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        if (n_discrete > 0) requireArg(discrete, "discrete (with n_discrete > 0)");
        if (n_continuous > 0) requireArg(continuous, "continuous (with n_continuous > 0)");
        if (action_mask == nullptr && n_actions != 0) requireArg(action_mask, "action_mask (with n_actions > 0)");
        if (n_continuous_actions > 0) requireArg(continuous_action, "continuous_action (with n_continuous_actions > 0)");
        use.agent().updateDemonstrated(reward, verve::ObservationView{discrete, n_discrete, continuous, n_continuous}, dt,
                                       action, verve::ContinuousActionView{continuous_action, n_continuous_actions},
                                       verve::ActionMask{action_mask, n_actions});
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_teach(verve_agent* agent, float praise) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        use.agent().teach(praise);
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_end_episode(verve_agent* agent, float final_reward) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        use.agent().endEpisode(final_reward);
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_truncate_episode(verve_agent* agent, float reward) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        use.agent().truncateEpisode(reward);
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_set_action_selection(verve_agent* agent, uint32_t mode) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        verve::Agent& a = use.agent();
        if (mode != VERVE_ACTION_SAMPLE && mode != VERVE_ACTION_GREEDY) {
            throw verve::Error(verve::ErrorCode::InvalidArgument,
                               "mode must be VERVE_ACTION_SAMPLE or VERVE_ACTION_GREEDY, got " + std::to_string(mode));
        }
        a.setActionSelection(static_cast<verve::ActionSelection>(mode));
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_get_action_selection(const verve_agent* agent, uint32_t* out_mode) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        const verve::Agent& a = use.agent();
        requireArg(out_mode, "out_mode");
        *out_mode = static_cast<uint32_t>(a.actionSelection());
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_reset_short_term_memory(verve_agent* agent) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        use.agent().resetShortTermMemory();
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_set_learning(verve_agent* agent, int enabled) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        use.agent().setLearning(enabled != 0);
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_get_learning(const verve_agent* agent, int* out_enabled) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        const verve::Agent& a = use.agent();
        requireArg(out_enabled, "out_enabled");
        *out_enabled = a.learning() ? 1 : 0;
    });
}

VERVE_API verve_result VERVE_CALL verve_agent_get_desc(const verve_agent* agent, verve_agent_desc* out) {
    return guarded(__func__, [&] {
        const AgentUse use(agent);
        const verve::Agent& a = use.agent();
        requireArg(out, "out");
        verve::capi::writeDesc(a.descriptor(), *out);
    });
}

}  // extern "C"
