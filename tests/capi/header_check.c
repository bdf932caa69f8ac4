/* Compiled as C99 (and, through header_check.cpp, as C++11) with -Wall -Wextra -pedantic
 * -Werror: the public header must stay clean for both. */
#include "verve_c.h"

/* The historical struct sizes are compile-time constants, the old one a strict prefix. */
typedef char verve_desc_v1_is_a_prefix[(VERVE_AGENT_DESC_SIZE_V1 < VERVE_AGENT_DESC_SIZE_V2) ? 1 : -1];
/* V2 ends where the V2 struct ended, tail padding included: hosts built then pass that sizeof. */
typedef char verve_desc_v2_is_the_old_struct[
    (VERVE_AGENT_DESC_SIZE_V2 == offsetof(verve_agent_desc, discrete_prediction) + 2 * sizeof(uint32_t)) ? 1 : -1];
typedef char verve_desc_v1_ends_after_seed[
    (VERVE_AGENT_DESC_SIZE_V1 == offsetof(verve_agent_desc, seed) + sizeof(uint64_t)) ? 1 : -1];

int verve_header_check_c(void);
int verve_header_check_c(void) {
    verve_agent_desc desc;
    verve_agent_stats stats;
    verve_value_axis axis = {VERVE_SENSOR_CONTINUOUS, 0, 10};
    verve_result r = VERVE_OK;
    verve_agent* agent = NULL;
    stats.struct_size = (uint32_t)sizeof stats;
    desc.struct_size = VERVE_AGENT_DESC_SIZE_V8;
    (void)agent;
    return (int)r + (int)axis.samples + (int)desc.struct_size + (int)stats.struct_size + VERVE_VERSION_NUMBER;
}
