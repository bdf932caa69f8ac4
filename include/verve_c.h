/*
 * verve_c.h - the stable C ABI of Verve, an embeddable reinforcement-learning agent.
 *
 * C99, no C++ types: load libverve as a native plugin and call only what is declared here.
 *
 * Conventions
 *  - Every function returns a verve_result (except verve_version, verve_last_error,
 *    verve_result_name and verve_agent_desc_default). On failure nothing changed, and
 *    verve_last_error() returns a message for the calling thread.
 *  - No exception, abort or assert reaches the host on any input, NULL pointers included.
 *  - Arrays are passed as pointer + count. Structs are plain and blittable.
 *  - verve_agent_desc starts with struct_size: fill it with verve_agent_desc_init(&d, sizeof d),
 *    which writes only the host's own struct, so a host compiled against an older, smaller struct
 *    keeps working with a newer library (verve_agent_desc_default writes the library's whole
 *    struct: safe only with the header the library was built from).
 *
 * Thread rules
 *  - One agent is used by one thread at a time. Different agents may be used concurrently.
 *    Overlapping calls on one agent are detected and refused with VERVE_ERROR_INVALID_STATE;
 *    a destroy during another call on the handle (agent, brain, batch) leaves it alive.
 *  - A shared brain and all its bodies count as one agent. verve_batch_update spreads many
 *    agents, and the bodies of a brain, over threads for you (docs/crowds.md).
 *  - verve_last_error() is per thread.
 *
 * Ownership
 *  - verve_agent_create / verve_agent_load / verve_agent_load_memory hand you an agent; free it
 *    with verve_agent_destroy. Buffers you pass are only read (or written) during the call.
 *  - A body (verve_brain_create_body) is an agent: free it with verve_agent_destroy. It keeps its
 *    brain alive, so brains and bodies may be destroyed in any order.
 */
#ifndef VERVE_C_H
#define VERVE_C_H

#include <stddef.h>
#include <stdint.h>

#define VERVE_VERSION_MAJOR 0
#define VERVE_VERSION_MINOR 1
#define VERVE_VERSION_PATCH 0
/* (major << 16) | (minor << 8) | patch */
#define VERVE_VERSION_NUMBER ((VERVE_VERSION_MAJOR << 16) | (VERVE_VERSION_MINOR << 8) | VERVE_VERSION_PATCH)

#if defined(_WIN32)
#  if defined(VERVE_BUILDING_LIBRARY)
#    define VERVE_API __declspec(dllexport)
#  else
#    define VERVE_API __declspec(dllimport)
#  endif
#  define VERVE_CALL __cdecl
#else
#  define VERVE_API __attribute__((visibility("default")))
#  define VERVE_CALL
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef enum verve_result {
    VERVE_OK = 0,
    VERVE_ERROR_INVALID_ARGUMENT = 1, /* NULL pointer, wrong count, NaN/inf, out-of-range value */
    VERVE_ERROR_INVALID_STATE = 2,    /* the call does not fit the agent's state */
    VERVE_ERROR_IO = 3,               /* a file could not be read, written or renamed */
    VERVE_ERROR_FORMAT = 4,           /* a save is corrupt, truncated or inconsistent */
    VERVE_ERROR_VERSION = 5,          /* a save written by a newer format version */
    VERVE_ERROR_OUT_OF_MEMORY = 6,
    VERVE_ERROR_BUFFER_TOO_SMALL = 7, /* the required size was written to the size argument */
    VERVE_ERROR_INTERNAL = 8
} verve_result;

typedef enum verve_rbf_allocation {
    VERVE_RBF_DYNAMIC = 0, /* RBFs are created where observations land (default) */
    VERVE_RBF_FULL = 1     /* the whole lattice is created up front */
} verve_rbf_allocation;

typedef enum verve_curiosity {
    VERVE_CURIOSITY_NONE = 0,
    VERVE_CURIOSITY_NOVELTY = 1, /* reward proportional to predicted uncertainty (thesis) */
    VERVE_CURIOSITY_PROGRESS = 2 /* reward for falling prediction error (ignores pure noise) */
} verve_curiosity;

typedef enum verve_discrete_prediction {
    VERVE_DISCRETE_PREDICTION_CATEGORICAL = 0, /* one model output per value (default) */
    VERVE_DISCRETE_PREDICTION_ORDINAL = 1      /* the original's single rounded scalar */
} verve_discrete_prediction;

typedef enum verve_sensor_grouping {
    VERVE_GROUPING_AUTO = 0,  /* one RBF lattice over up to 4 continuous sensors; beyond that one per
                                 sensor and one per neighbouring pair (i, i + 1): list related
                                 sensors (adjacent rays, bearing and distance) next to each other */
    VERVE_GROUPING_JOINT = 1, /* one lattice over all continuous sensors (the thesis): resolution^n RBFs */
    VERVE_GROUPING_CUSTOM = 2 /* the lattices listed in sensor_groups */
} verve_sensor_grouping;

typedef enum verve_action_selection {
    VERVE_ACTION_SAMPLE = 0, /* draw each action with its probability: explores, learns (default) */
    VERVE_ACTION_GREEDY = 1  /* always the most probable action: deterministic play, a shipped NPC */
} verve_action_selection;

typedef enum verve_sensor_kind {
    VERVE_SENSOR_DISCRETE = 0,
    VERVE_SENSOR_CONTINUOUS = 1
} verve_sensor_kind;

#define VERVE_MAX_DISCRETE_SENSORS 16   /* in the V1-V7 arrays; V8 holds up to VERVE_MAX_SENSORS */
#define VERVE_MAX_CONTINUOUS_SENSORS 16 /* in the V1-V7 arrays; V8 holds up to VERVE_MAX_SENSORS */
#define VERVE_MAX_SENSORS 64            /* of each kind, with a V8 struct (a sensor group is 64 bits) */
#define VERVE_MAX_LATTICE_SENSORS 16    /* continuous sensors one RBF lattice spans: JOINT and each
                                           CUSTOM group at most this many */
#define VERVE_MAX_SENSOR_GROUPS 64
#define VERVE_MAX_ACTION_BRANCHES 8
#define VERVE_MAX_CONTINUOUS_ACTIONS 8

typedef struct verve_agent verve_agent; /* opaque */
typedef struct verve_brain verve_brain; /* opaque: a learner shared by many bodies (agents) */
typedef struct verve_batch verve_batch; /* opaque: updates many agents in one call */
typedef struct verve_recording verve_recording; /* opaque: demonstrated steps kept for replay */

typedef struct verve_agent_desc {
    uint32_t struct_size; /* sizeof(verve_agent_desc), set by verve_agent_desc_default */

    uint32_t num_discrete_sensors;
    uint32_t discrete_sensor_values[VERVE_MAX_DISCRETE_SENSORS]; /* values per discrete sensor */
    uint32_t num_continuous_sensors;
    uint8_t continuous_sensor_circular[VERVE_MAX_CONTINUOUS_SENSORS]; /* 1: the range wraps */
    uint32_t resolution;  /* RBFs across [-1, 1] per continuous sensor (default 10) */
    uint32_t num_actions;
    uint32_t rbf_allocation; /* verve_rbf_allocation */

    float tau_value;          /* seconds (default 0.1) */
    float tau_discount;       /* seconds (default 1.0) */
    float tau_eligibility;    /* seconds (default 0.1) */
    float policy_multiplier;  /* default 5 */
    float trace_threshold;    /* default 0.01 */
    uint64_t seed;

    uint32_t planning;                     /* 0 or 1 (default 0) */
    float tau_model;                       /* seconds (default 0: learning rate 1) */
    uint32_t max_planning_steps;           /* default 10 */
    float planning_uncertainty_threshold;  /* default 0.5 (uncertainty is a normalised error in [0, 1]) */
    uint32_t curiosity;                    /* verve_curiosity (default NONE) */
    float curiosity_factor;                /* default 5 */
    uint32_t planning_accumulates_uncertainty; /* 1 (default): a plan stops on its summed uncertainty */
    uint32_t learn_from_real_steps;        /* 1 (default, Dyna): real steps train too, not only plans */
    uint32_t discrete_prediction;          /* verve_discrete_prediction (default CATEGORICAL) */

    /* V3. 64 bits wide so that it starts exactly where V2 ended (V2 had 4 bytes of tail padding). */
    uint64_t max_rbfs; /* RBF budget (default 1000000; 0: unlimited, up to 2^32 - 2). At the budget the
                          agent keeps working with the RBFs it has and counts rbf_budget_hits */
    float policy_weight_bound;             /* > 0: actor weights stay within +-bound, so habits can be
                                              unlearned when the world changes; 0 (default): only
                                              VERVE_ADAPT_HABIT_BOUND's ceiling of +10, if set */

    /* V4. 64 bits wide so that it starts exactly where V3 ended (V3 had 4 bytes of tail padding). */
    uint64_t adaptation; /* VERVE_ADAPT_* bits: settings the agent sets for itself from what it
                            experiences (default VERVE_ADAPT_ALL; 0: every setting as given) */

    /* V5: which continuous sensors share an RBF lattice (docs/algorithm.md, "Many sensors"). */
    uint32_t sensor_grouping;   /* verve_sensor_grouping (default AUTO) */
    uint32_t num_sensor_groups; /* CUSTOM: how many entries of sensor_groups are used (else 0) */
    uint64_t sensor_groups[VERVE_MAX_SENSOR_GROUPS]; /* CUSTOM: bit i set = continuous sensor i is in
                                                        the group; every sensor in at least one */

    /* V6: action branches (docs/algorithm.md, "Action branches"): several choices on every step,
       e.g. {3, 3, 2} for move x turn x use, each by an actor head of its own. An action is then the
       combined index a0 + n0 * (a1 + n1 * (a2 + ...)): verve_agent_split_action and
       verve_agent_join_action convert. Planning needs one action set. */
    uint32_t num_action_branches; /* 0 (default): one set of num_actions actions */
    uint32_t action_branches[VERVE_MAX_ACTION_BRANCHES]; /* choices per branch (>= 1 each); num_actions
                                                            is then 0 (set to their product) or it */

    /* V7: continuous actions (docs/algorithm.md, "Continuous actions"): this many values in [-1, 1]
       chosen on every step beside the discrete action (steering, throttle, a torque), read with
       verve_agent_get_continuous_action. An agent with continuous actions only keeps one discrete
       action: num_actions 0 then means 1. Planning needs discrete actions only. 64 bits wide so
       that it starts exactly where V6 ended (V6 had 4 bytes of tail padding). */
    uint64_t num_continuous_actions; /* 0 (default) .. VERVE_MAX_CONTINUOUS_ACTIONS */

    /* V8: up to VERVE_MAX_SENSORS sensors of each kind (num_discrete_sensors and
       num_continuous_sensors up to 64). Sensor i < 16 is still described in the arrays above; sensor
       16 + j here. Starts exactly where V7 ended (V7's last field is 64 bits: no tail padding), and
       240 bytes keep the struct's size a multiple of 8. More than 16 continuous sensors need AUTO
       (up to 32 sensors) or CUSTOM groups: one lattice spans at most VERVE_MAX_LATTICE_SENSORS. */
    uint32_t more_discrete_sensor_values[VERVE_MAX_SENSORS - VERVE_MAX_DISCRETE_SENSORS];
    uint8_t more_continuous_sensor_circular[VERVE_MAX_SENSORS - VERVE_MAX_CONTINUOUS_SENSORS];
} verve_agent_desc;

/* verve_agent_desc.adaptation bits (docs/algorithm.md, "Learning at defaults"). */
#define VERVE_ADAPT_HORIZON 1u      /* the discount horizon follows how long trials last (their longest
                                       stretches of an unchanged step reward); tau_discount is then its
                                       shortest */
#define VERVE_ADAPT_ACTOR_SCALE 2u  /* the actor's steps stay reward-sized when TD errors grow */
#define VERVE_ADAPT_DECISION_RATE 4u /* an update less than 0.1 s after the previous one learns as much
                                        as a 0.1 s decision (learning rates, trace decay) */
#define VERVE_ADAPT_HABIT_BOUND 8u  /* with policy_weight_bound 0, actor weights stay at or below +10,
                                       so a habit a changed world makes wrong can be unlearned */
#define VERVE_ADAPT_FINE_LATTICE 16u /* one or two continuous sensors get a second RBF lattice at twice
                                        the resolution beside the first (saves made without it keep
                                        their one lattice) */
#define VERVE_ADAPT_PAIRS_BESIDE 32u /* three or four continuous sensors under VERVE_GROUPING_AUTO get,
                                        beside their lattice, one over each neighbouring pair (saves
                                        made without it keep their one lattice) */
#define VERVE_ADAPT_GROUP_RATES 64u /* two or more sensor groups learn at rates of their own, learned
                                         from the TD errors: those that predict them take more of each
                                         step (saves made without it keep one rate for all) */
#define VERVE_ADAPT_ALL 127u

/* The sizes of verve_agent_desc a library accepts in struct_size: each release's full struct.
 * V1 ended after `seed` (no planning fields); V2 after discrete_prediction; V3 after
 * policy_weight_bound; V4 after adaptation; V5 after sensor_groups; V6 after action_branches; V7 after
 * num_continuous_actions (at most 16 sensors of each kind); V8 is the current struct. Fields beyond a smaller
 * struct_size take their defaults. Any other size is refused. */
#define VERVE_AGENT_DESC_SIZE_V1 ((uint32_t)offsetof(verve_agent_desc, planning))
#define VERVE_AGENT_DESC_SIZE_V2 ((uint32_t)offsetof(verve_agent_desc, max_rbfs))
#define VERVE_AGENT_DESC_SIZE_V3 ((uint32_t)offsetof(verve_agent_desc, adaptation))
#define VERVE_AGENT_DESC_SIZE_V4 ((uint32_t)offsetof(verve_agent_desc, sensor_grouping))
#define VERVE_AGENT_DESC_SIZE_V5 ((uint32_t)offsetof(verve_agent_desc, num_action_branches))
#define VERVE_AGENT_DESC_SIZE_V6 ((uint32_t)offsetof(verve_agent_desc, num_continuous_actions))
#define VERVE_AGENT_DESC_SIZE_V7 ((uint32_t)offsetof(verve_agent_desc, more_discrete_sensor_values))
#define VERVE_AGENT_DESC_SIZE_V8 ((uint32_t)sizeof(verve_agent_desc))

typedef struct verve_agent_stats {
    uint32_t struct_size;           /* VERVE_AGENT_STATS_SIZE_V1 or _V2 (sizeof): only that many bytes are written */
    uint64_t steps;                 /* real updates since creation */
    uint32_t rbf_count;
    uint32_t live_traces;
    float value;                    /* V(s) of the latest observation */
    float td_error;                 /* TD error of the latest real step */
    float model_error;              /* running mean squared prediction error */
    float predicted_uncertainty;
    uint32_t planning_steps;        /* imagined steps after the latest real step */
    float curiosity_reward;         /* summed over the latest plan */
    /* V2 */
    uint64_t rbf_budget_hits;       /* updates that would have made an RBF but max_rbfs was reached */
    uint64_t clamped_rewards;       /* rewards outside [-1, 1] that were clamped */
} verve_agent_stats;

#define VERVE_AGENT_STATS_SIZE_V1 ((uint32_t)offsetof(verve_agent_stats, rbf_budget_hits))
#define VERVE_AGENT_STATS_SIZE_V2 ((uint32_t)sizeof(verve_agent_stats))

typedef struct verve_value_axis {
    uint32_t kind;    /* verve_sensor_kind */
    uint32_t index;   /* which sensor of that kind */
    uint32_t samples; /* continuous: points from -1 to 1; discrete: the sensor's value count */
} verve_value_axis;

/* Host hooks: where Verve's memory comes from and where its warnings go (engines and consoles
 * route both through their own systems). */
typedef void* (VERVE_CALL *verve_malloc_fn)(void* user, size_t size);      /* NULL when out of memory */
typedef void* (VERVE_CALL *verve_realloc_fn)(void* user, void* block, size_t size);
typedef void (VERVE_CALL *verve_free_fn)(void* user, void* block);        /* block is never NULL */

typedef enum verve_log_level {
    VERVE_LOG_WARNING = 1 /* the call succeeded, but the host should know (clamped input, a budget reached) */
} verve_log_level;
typedef void (VERVE_CALL *verve_log_fn)(void* user, verve_log_level level, const char* message);

typedef struct verve_hooks {
    uint32_t struct_size;        /* sizeof(verve_hooks) */
    /* Verve's memory: malloc_fn and free_fn both set, or both NULL (the C library's). Not routed:
     * exception objects in flight, the batch pool's thread stacks, and everything on Apple
     * platforms (not self-contained there yet; only log_fn is taken). Blocks must be aligned for
     * any standard type (like malloc). realloc_fn may be NULL: this version never calls it. */
    verve_malloc_fn malloc_fn;
    verve_realloc_fn realloc_fn;
    verve_free_fn free_fn;
    void* alloc_user;            /* passed to the three functions */
    verve_log_fn log_fn;         /* NULL: warnings are dropped */
    void* log_user;
} verve_hooks;

#define VERVE_HOOKS_SIZE_V1 ((uint32_t)sizeof(verve_hooks))

/* ---- library ---------------------------------------------------------------------------- */
VERVE_API uint32_t VERVE_CALL verve_version(void); /* VERVE_VERSION_NUMBER of the loaded library */
VERVE_API const char* VERVE_CALL verve_last_error(void); /* never NULL; "" after success */
VERVE_API const char* VERVE_CALL verve_result_name(verve_result result);
/* Installs the allocator and log hooks (NULL: back to the C library and no log). Only while Verve
 * holds no memory (before the first agent, or after the last is destroyed), and not concurrently
 * with other Verve calls: VERVE_ERROR_INVALID_STATE otherwise. The hooks may be called from any
 * thread that calls Verve, concurrently when several agents are used at once. */
VERVE_API verve_result VERVE_CALL verve_set_hooks(const verve_hooks* hooks);

/* ---- agents ----------------------------------------------------------------------------- */
VERVE_API void VERVE_CALL verve_agent_desc_default(verve_agent_desc* desc); /* NULL is ignored */
/* Defaults for a struct of struct_size bytes (one of the VERVE_AGENT_DESC_SIZE_* values): writes
 * only that many bytes, so a host built against an older header may call it with sizeof(its struct)
 * on any newer library. verve_agent_desc_default(d) is verve_agent_desc_init(d, sizeof *d). */
VERVE_API verve_result VERVE_CALL verve_agent_desc_init(verve_agent_desc* desc, uint32_t struct_size);
VERVE_API verve_result VERVE_CALL verve_agent_create(const verve_agent_desc* desc, verve_agent** out);
VERVE_API void VERVE_CALL verve_agent_destroy(verve_agent* agent); /* NULL is ignored */

/* One step. reward: what the previous action earned (clamped to [-1, 1]). Continuous values
 * outside [-1, 1] are clamped (wrapped when circular); NaN/inf, a wrong count, an out-of-range
 * discrete value or dt <= 0 are refused and change nothing. */
VERVE_API verve_result VERVE_CALL verve_agent_update(verve_agent* agent, float reward,
    const int32_t* discrete, uint32_t n_discrete, const float* continuous, uint32_t n_continuous,
    float dt, uint32_t* out_action);
/* verve_agent_update choosing only among the actions the mask allows this step: action_mask holds
 * n_actions flags (the agent's num_actions), 1 allowed, 0 not, at least one 1. A masked action is
 * never chosen and gets no credit. With action branches, one flag per choice of each branch, branch
 * after branch (n_actions = the branches' sizes summed), at least one 1 in each branch. */
VERVE_API verve_result VERVE_CALL verve_agent_update_masked(verve_agent* agent, float reward,
    const int32_t* discrete, uint32_t n_discrete, const float* continuous, uint32_t n_continuous,
    float dt, const uint8_t* action_mask, uint32_t n_actions, uint32_t* out_action);
/* A demonstrated step (docs/teaching.md): as verve_agent_update, but the host took `action` (a player
 * or the game's scripted AI drove the NPC). The agent learns from it as from its own choice and is
 * pulled towards it; the next verve_agent_update acts on its own again. action_mask: NULL with
 * n_actions 0 for every action, or flags as in verve_agent_update_masked. An action out of range or
 * forbidden by the mask is refused and changes nothing. */
VERVE_API verve_result VERVE_CALL verve_agent_update_demonstrated(verve_agent* agent, float reward,
    const int32_t* discrete, uint32_t n_discrete, const float* continuous, uint32_t n_continuous,
    float dt, const uint8_t* action_mask, uint32_t n_actions, uint32_t action);
/* verve_agent_update_demonstrated with the teacher's continuous actions too: continuous_action holds
 * n_continuous_actions values (the agent's num_continuous_actions), each in [-1, 1], that the host
 * played (a player's steering and throttle). The agent learns from them as from values it drew
 * itself and is pulled towards them; verve_agent_get_continuous_action then reads them back. A wrong
 * count, NULL with a count above 0, NaN or a value outside [-1, 1] is refused and changes nothing. */
VERVE_API verve_result VERVE_CALL verve_agent_update_demonstrated_continuous(verve_agent* agent, float reward,
    const int32_t* discrete, uint32_t n_discrete, const float* continuous, uint32_t n_continuous,
    float dt, const uint8_t* action_mask, uint32_t n_actions, uint32_t action,
    const float* continuous_action, uint32_t n_continuous_actions);
/* A teacher's judgement (docs/teaching.md): praise in [-1, 1] (1 good, -1 bad) of what the agent did
 * over the last 2.5 s, as a player's click arrives 0.2-2 s after the act it judges. It moves the
 * actor's preferences for those acts (continuous actions' means towards the values played, or away
 * when scolded) and is not a reward. The agent remembers its acts from its first
 * judgement on (praise 0 arms the memory without judging); the memory is not saved. NaN or praise
 * outside [-1, 1] is refused and changes nothing. */
VERVE_API verve_result VERVE_CALL verve_agent_teach(verve_agent* agent, float praise);
/* Ends a trial that really ended (goal reached, NPC died): final_reward is learned as the last
 * reward there is, nothing is expected after it. */
VERVE_API verve_result VERVE_CALL verve_agent_end_episode(verve_agent* agent, float final_reward);
/* Ends a trial that was cut off (a time limit, a level reset) where the world would have gone on:
 * reward (what the last action earned) is learned, and the last state's value stands in for what
 * would have followed. Use it instead of verve_agent_end_episode when the end was not the task's. */
VERVE_API verve_result VERVE_CALL verve_agent_truncate_episode(verve_agent* agent, float reward);
VERVE_API verve_result VERVE_CALL verve_agent_reset_short_term_memory(verve_agent* agent);
VERVE_API verve_result VERVE_CALL verve_agent_set_learning(verve_agent* agent, int enabled);
VERVE_API verve_result VERVE_CALL verve_agent_get_learning(const verve_agent* agent, int* out_enabled);
/* out->struct_size must be set (verve_agent_desc_init does it); only that many bytes are written. */
VERVE_API verve_result VERVE_CALL verve_agent_get_desc(const verve_agent* agent, verve_agent_desc* out);

/* Action branches: the choice of each branch within a combined action (out_choices: n_branches
 * values, n_branches = the agent's num_action_branches, or 1 with one action set), and the combined
 * action of one choice per branch. A wrong count, an action or a choice out of range is refused. */
VERVE_API verve_result VERVE_CALL verve_agent_split_action(const verve_agent* agent, uint32_t action,
    uint32_t* out_choices, uint32_t n_branches);
VERVE_API verve_result VERVE_CALL verve_agent_join_action(const verve_agent* agent, const uint32_t* choices,
    uint32_t n_branches, uint32_t* out_action);

/* How verve_agent_update picks its action: a verve_action_selection. Per agent, not saved. */
VERVE_API verve_result VERVE_CALL verve_agent_set_action_selection(verve_agent* agent, uint32_t mode);
VERVE_API verve_result VERVE_CALL verve_agent_get_action_selection(const verve_agent* agent, uint32_t* out_mode);

/* ---- read-outs -------------------------------------------------------------------------- */
/* The policy's probability of each action at the latest update (count = num_actions floats summing
 * to 1; 0 for masked actions): what VERVE_ACTION_SAMPLE drew from. Uniform before any update. With
 * action branches, each branch's choices in turn (count = the branches' sizes summed), each branch's
 * summing to 1. */
VERVE_API verve_result VERVE_CALL verve_agent_get_action_probabilities(const verve_agent* agent, float* out,
    uint32_t count);
/* The continuous actions of the latest update (count = num_continuous_actions floats, each in
 * [-1, 1]): sampled around the policy's mean, or the mean itself with VERVE_ACTION_GREEDY or on a
 * demonstrated step (the teacher's values after verve_agent_update_demonstrated_continuous). 0s
 * before any update. A wrong count is refused. */
VERVE_API verve_result VERVE_CALL verve_agent_get_continuous_action(const verve_agent* agent, float* out,
    uint32_t count);
VERVE_API verve_result VERVE_CALL verve_agent_get_value(const verve_agent* agent, float* out_value);
VERVE_API verve_result VERVE_CALL verve_agent_get_td_error(const verve_agent* agent, float* out_td_error);
VERVE_API verve_result VERVE_CALL verve_agent_get_rbf_count(const verve_agent* agent, uint32_t* out_count);
VERVE_API verve_result VERVE_CALL verve_agent_get_stats(const verve_agent* agent, verve_agent_stats* out);
/* V sampled over 1 or 2 swept sensors, the other sensors held at the base observation.
 * Writes axes[0].samples (* axes[1].samples) floats to out, axis 0 fastest. */
VERVE_API verve_result VERVE_CALL verve_agent_sample_values(const verve_agent* agent,
    const verve_value_axis* axes, uint32_t n_axes,
    const int32_t* base_discrete, uint32_t n_discrete, const float* base_continuous, uint32_t n_continuous,
    float* out, uint32_t out_count);

/* ---- persistence (XML or compact binary) ------------------------------------------------- */
/* Atomic: written to a temporary file, flushed and renamed, so the previous save survives a crash;
 * the replaced file's permissions and owner are kept. The agent is serialised under its in-use
 * flag, the file written after the flag is given back (the disk never holds up updates). A failed
 * directory flush is VERVE_ERROR_IO (the new save in place). Load (file or memory) reads either
 * format, told apart by its first bytes. */
VERVE_API verve_result VERVE_CALL verve_agent_save(const verve_agent* agent, const char* path);
VERVE_API verve_result VERVE_CALL verve_agent_load(const char* path, verve_agent** out);
/* To memory: call with buffer NULL (or too small) to get the size needed in *size
 * (VERVE_ERROR_BUFFER_TOO_SMALL when buffer was non-NULL); then call again with a buffer. */
VERVE_API verve_result VERVE_CALL verve_agent_save_memory(const verve_agent* agent, void* buffer, size_t* size);
VERVE_API verve_result VERVE_CALL verve_agent_load_memory(const void* data, size_t size, verve_agent** out);
/* The same saves in the compact binary format (checksummed, little-endian; several times faster
 * than XML to save and to load). */
VERVE_API verve_result VERVE_CALL verve_agent_save_binary(const verve_agent* agent, const char* path);
VERVE_API verve_result VERVE_CALL verve_agent_save_memory_binary(const verve_agent* agent, void* buffer, size_t* size);

/* ---- one brain, many bodies ------------------------------------------------------------ */
/* A brain holds RBFs, weights and model; each body is a verve_agent with its own short-term
 * memory (traces, previous step, random stream) that learns into the brain's shared weights.
 * Every verve_agent_* call works on a body; saving a body saves the brain plus its memory. */
VERVE_API verve_result VERVE_CALL verve_brain_create(const verve_agent_desc* desc, verve_brain** out);
/* NULL is ignored. Refused (the brain stays alive, verve_last_error says so) while a call on the
 * brain runs on another thread; its bodies may be in calls: they keep the brain's data alive. */
VERVE_API void VERVE_CALL verve_brain_destroy(verve_brain* brain);
/* Body k of a brain (k counts the bodies it made) draws from a random stream of (seed, k). */
VERVE_API verve_result VERVE_CALL verve_brain_create_body(verve_brain* brain, verve_agent** out_body);
VERVE_API verve_result VERVE_CALL verve_brain_get_rbf_count(const verve_brain* brain, uint32_t* out_count);
/* Saves are agent saves without short-term memory: a brain save loads as an agent and an agent
 * save loads as a brain, in either format (loads tell XML and binary apart). The memory calls
 * follow verve_agent_save_memory's two-call pattern (serialised once for both calls). */
VERVE_API verve_result VERVE_CALL verve_brain_save(const verve_brain* brain, const char* path);
VERVE_API verve_result VERVE_CALL verve_brain_load(const char* path, verve_brain** out);
VERVE_API verve_result VERVE_CALL verve_brain_save_memory(const verve_brain* brain, void* buffer, size_t* size);
VERVE_API verve_result VERVE_CALL verve_brain_load_memory(const void* data, size_t size, verve_brain** out);
/* The same saves in the compact binary format (as verve_agent_save_binary's). */
VERVE_API verve_result VERVE_CALL verve_brain_save_binary(const verve_brain* brain, const char* path);
VERVE_API verve_result VERVE_CALL verve_brain_save_memory_binary(const verve_brain* brain, void* buffer, size_t* size);

/* ---- many agents in one call ------------------------------------------------------------ */
/* A host job system (as Box2D v3's b2WorldDef takes one): enqueue_task runs task over
 * [0, item_count) in ranges of at least min_range items, on its workers, with worker_index below
 * verve_batch_desc.worker_count, and returns a handle that finish_task waits on (NULL: the task
 * already ran inline; finish_task is not called). Both are called from the updating thread only. */
typedef void (VERVE_CALL *verve_task_fn)(uint32_t start, uint32_t end, uint32_t worker_index, void* task_context);
typedef void* (VERVE_CALL *verve_enqueue_task_fn)(verve_task_fn task, uint32_t item_count, uint32_t min_range,
                                                   void* task_context, void* user_context);
typedef void (VERVE_CALL *verve_finish_task_fn)(void* user_task, void* user_context);

typedef struct verve_batch_desc {
    uint32_t struct_size;   /* sizeof(verve_batch_desc), set by verve_batch_desc_default */
    uint32_t worker_count;  /* threads incl. the caller; 0 (default): the machine's; with callbacks: the host's */
    verve_enqueue_task_fn enqueue_task; /* both NULL (default): Verve's own pool, started lazily */
    verve_finish_task_fn finish_task;
    void* user_context;     /* handed to the callbacks */
} verve_batch_desc;

VERVE_API verve_result VERVE_CALL verve_batch_desc_default(verve_batch_desc* desc);
VERVE_API verve_result VERVE_CALL verve_batch_create(const verve_batch_desc* desc, verve_batch** out);
/* Joins its threads; NULL is ignored; refused (the batch stays alive) while a call on it runs. */
VERVE_API void VERVE_CALL verve_batch_destroy(verve_batch* batch);
/* A batch is used by one thread at a time, like an agent (an overlapping call is refused). */
VERVE_API verve_result VERVE_CALL verve_batch_get_worker_count(const verve_batch* batch, uint32_t* out_count);
/* One step of n agents (any shapes, separate agents or bodies), the same on any number of threads:
 * separate agents exactly as n verve_agent_update calls in array order would do it, the bodies of a
 * brain in parallel phases whose result depends only on their order (docs/crowds.md). Agent i reads rewards[i] and its
 * observation from the packed arrays: at discrete_offsets[i] / continuous_offsets[i] when given,
 * else right after agent i-1's values (agents packed back to back). discrete_total and
 * continuous_total are the arrays' lengths. Everything is checked first: on any bad input nothing
 * changes, out_results (optional, n entries) gets each agent's verdict and the call returns the
 * first agent's error. A refusal of the whole call (NULL arrays, a bad dt, a handle in use, the
 * pool's threads failing to start) writes the call's result into every out_results entry. An
 * update failing later (out of memory) leaves that agent unchanged, the others updated, and is
 * reported the same way. No failure, a thread that cannot start included, takes the host down. */
VERVE_API verve_result VERVE_CALL verve_batch_update(verve_batch* batch, verve_agent* const* agents, uint32_t n,
    const float* rewards,
    const int32_t* discrete, const uint32_t* discrete_offsets, uint32_t discrete_total,
    const float* continuous, const uint32_t* continuous_offsets, uint32_t continuous_total,
    float dt, uint32_t* out_actions, verve_result* out_results);
/* verve_batch_update with demonstrated steps (docs/teaching.md): demonstrated[i] is the action the
 * host took for agent i (as verve_agent_update_demonstrated; out_actions[i] gets it back), or
 * VERVE_AGENT_CHOOSES for the agent's own choice (demonstrated NULL: every agent chooses). A
 * demonstrated action out of range is refused with the rest of the checks, before anything changes. */
#define VERVE_AGENT_CHOOSES 0xFFFFFFFFu
VERVE_API verve_result VERVE_CALL verve_batch_update_demonstrated(verve_batch* batch, verve_agent* const* agents,
    uint32_t n, const float* rewards,
    const int32_t* discrete, const uint32_t* discrete_offsets, uint32_t discrete_total,
    const float* continuous, const uint32_t* continuous_offsets, uint32_t continuous_total,
    float dt, const uint32_t* demonstrated, uint32_t* out_actions, verve_result* out_results);
/* verve_batch_update_demonstrated with the teacher's continuous actions too (as
 * verve_agent_update_demonstrated_continuous takes them): agent i's num_continuous_actions values in
 * continuous_actions at continuous_action_offsets[i] when given, else right after agent i-1's
 * (every agent's count, shown or not, packed back to back); continuous_actions_total is the array's
 * length. They are read only for agents shown an action, and checked with the rest (a value outside
 * [-1, 1], NaN or values outside the array refuse the call before anything changes).
 * continuous_actions NULL: as verve_batch_update_demonstrated (the policy's means are played). */
VERVE_API verve_result VERVE_CALL verve_batch_update_demonstrated_continuous(verve_batch* batch,
    verve_agent* const* agents, uint32_t n, const float* rewards,
    const int32_t* discrete, const uint32_t* discrete_offsets, uint32_t discrete_total,
    const float* continuous, const uint32_t* continuous_offsets, uint32_t continuous_total,
    float dt, const uint32_t* demonstrated, const float* continuous_actions,
    const uint32_t* continuous_action_offsets, uint32_t continuous_actions_total,
    uint32_t* out_actions, verve_result* out_results);

/* Recordings (docs/teaching.md, "Recordings"): demonstrated steps kept in memory or in a file
 * (checksummed, versioned, bounded like a save) and replayed into an agent to train it before it
 * ships. A recording has an agent's sensors and actions; every entry is checked as it is added (a
 * refused one is not recorded) and again when a file is loaded. One thread at a time per recording
 * (a second is refused with VERVE_ERROR_INVALID_STATE). */
VERVE_API verve_result VERVE_CALL verve_recording_create(const verve_agent* shaped_like, verve_recording** out);
VERVE_API void VERVE_CALL verve_recording_destroy(verve_recording* recording); /* NULL is ignored */
/* As verve_agent_update_demonstrated takes them (no mask), verve_agent_end_episode and
 * verve_agent_truncate_episode. At most 2^26 entries (VERVE_ERROR_INVALID_STATE beyond). */
VERVE_API verve_result VERVE_CALL verve_recording_add_step(verve_recording* recording, float reward,
    const int32_t* discrete, uint32_t n_discrete, const float* continuous, uint32_t n_continuous,
    float dt, uint32_t action);
/* As verve_agent_update_demonstrated_continuous takes them (no mask): n_continuous_actions must be
 * the num_continuous_actions of the agent the recording was created from. */
VERVE_API verve_result VERVE_CALL verve_recording_add_step_continuous(verve_recording* recording, float reward,
    const int32_t* discrete, uint32_t n_discrete, const float* continuous, uint32_t n_continuous,
    float dt, uint32_t action, const float* continuous_action, uint32_t n_continuous_actions);
VERVE_API verve_result VERVE_CALL verve_recording_add_end_episode(verve_recording* recording, float final_reward);
VERVE_API verve_result VERVE_CALL verve_recording_add_truncation(verve_recording* recording, float reward);
/* Entries (steps and trial ends) so far. */
VERVE_API verve_result VERVE_CALL verve_recording_get_size(const verve_recording* recording, uint64_t* out_entries);
VERVE_API verve_result VERVE_CALL verve_recording_save(const verve_recording* recording, const char* path);
/* The two-call pattern of verve_agent_save_memory. */
VERVE_API verve_result VERVE_CALL verve_recording_save_memory(const verve_recording* recording, void* buffer, size_t* size);
VERVE_API verve_result VERVE_CALL verve_recording_load(const char* path, verve_recording** out);
VERVE_API verve_result VERVE_CALL verve_recording_load_memory(const void* data, size_t size, verve_recording** out);
/* Every entry into the agent, in order, as demonstrated steps and trial ends. The agent must have
 * the recording's sensors and actions (else VERVE_ERROR_INVALID_ARGUMENT, nothing replayed); only
 * running out of memory can stop a replay part-way, and the agent then keeps the entries before. */
VERVE_API verve_result VERVE_CALL verve_agent_replay(verve_agent* agent, const verve_recording* recording);

#ifdef __cplusplus
}
#endif

#endif /* VERVE_C_H */
