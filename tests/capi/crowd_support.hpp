// What the crowd tests (crowd_test.cpp, crowd_demonstration_test.cpp) share: an agent's or a brain's
// XML save as a string, and a batch of `workers` threads of Verve's own pool.
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "verve_c.h"

namespace verve_crowd_test {

template <typename Handle>
std::string savedWith(const Handle* handle, verve_result (*save)(const Handle*, void*, size_t*)) {
    size_t size = 0;
    EXPECT_EQ(save(handle, nullptr, &size), VERVE_OK);
    std::string xml(size, '\0');
    EXPECT_EQ(save(handle, &xml[0], &size), VERVE_OK);
    return xml;
}
inline std::string saved(const verve_agent* agent) { return savedWith(agent, verve_agent_save_memory); }
inline std::string saved(const verve_brain* brain) { return savedWith(brain, verve_brain_save_memory); }

inline verve_batch* makeBatch(uint32_t workers) {
    verve_batch_desc d;
    EXPECT_EQ(verve_batch_desc_default(&d), VERVE_OK);
    d.worker_count = workers;
    verve_batch* b = nullptr;
    EXPECT_EQ(verve_batch_create(&d, &b), VERVE_OK) << verve_last_error();
    return b;
}

}  // namespace verve_crowd_test
