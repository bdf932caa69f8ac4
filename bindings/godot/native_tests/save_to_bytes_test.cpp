// The Godot binding's save to memory (vg_save_to_bytes, behind VerveAgent.save_bytes(),
// VerveBrain.save_bytes() and VerveRecording.save_bytes()) against a stand-in for Godot's API: a PoolByteArray that cannot grow
// must be an error, never a wrong-sized array returned as success (issue 32), and every failing
// allocation inside Verve during the save must be an error, never a crash. No engine needed.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

extern "C" {
#include "gd_api.h"
#include "gd_call.h"
}

namespace {

// ---- a stand-in for the few Godot calls the save path makes --------------------------------
struct Fake {
    bool growFails = false;  // godot_pool_byte_array_resize leaves the array as it was
    std::vector<std::string> errors;
};
Fake fake;

std::vector<std::uint8_t>*& vec(godot_pool_byte_array* a) { return *reinterpret_cast<std::vector<std::uint8_t>**>(a); }
const std::vector<std::uint8_t>* vec(const godot_pool_byte_array* a) {
    return *reinterpret_cast<std::vector<std::uint8_t>* const*>(a);
}
struct Variant {  // our layout inside godot_variant
    int type;
    std::vector<std::uint8_t>* bytes;
};
static_assert(sizeof(Variant) <= sizeof(godot_variant), "godot_variant holds the stand-in's variant");
Variant& var(godot_variant* v) { return *reinterpret_cast<Variant*>(v); }

void GDAPI arrayNew(godot_pool_byte_array* a) { vec(a) = new std::vector<std::uint8_t>(); }
void GDAPI arrayResize(godot_pool_byte_array* a, const godot_int size) {
    if (!fake.growFails) vec(a)->resize(static_cast<std::size_t>(size));
}
godot_int GDAPI arraySize(const godot_pool_byte_array* a) { return static_cast<godot_int>(vec(a)->size()); }
void GDAPI arrayDestroy(godot_pool_byte_array* a) { delete vec(a); }
godot_pool_byte_array_write_access* GDAPI arrayWrite(godot_pool_byte_array* a) {
    return reinterpret_cast<godot_pool_byte_array_write_access*>(vec(a));
}
uint8_t* GDAPI writePtr(const godot_pool_byte_array_write_access* w) {
    auto* v = reinterpret_cast<std::vector<std::uint8_t>*>(const_cast<godot_pool_byte_array_write_access*>(w));
    return v->empty() ? nullptr : v->data();  // as Godot: an empty PoolVector has no buffer
}
void GDAPI writeDestroy(godot_pool_byte_array_write_access*) {}
void GDAPI variantNewArray(godot_variant* v, const godot_pool_byte_array* a) {
    var(v) = Variant{GODOT_VARIANT_TYPE_POOL_BYTE_ARRAY, new std::vector<std::uint8_t>(*vec(a))};
}
void GDAPI variantNewNil(godot_variant* v) { var(v) = Variant{GODOT_VARIANT_TYPE_NIL, nullptr}; }
void GDAPI printError(const char* description, const char*, const char*, int) { fake.errors.emplace_back(description); }

godot_gdnative_core_api_struct makeCore() {
    godot_gdnative_core_api_struct core;
    std::memset(&core, 0, sizeof core);
    core.godot_pool_byte_array_new = arrayNew;
    core.godot_pool_byte_array_resize = arrayResize;
    core.godot_pool_byte_array_size = arraySize;
    core.godot_pool_byte_array_destroy = arrayDestroy;
    core.godot_pool_byte_array_write = arrayWrite;
    core.godot_pool_byte_array_write_access_ptr = writePtr;
    core.godot_pool_byte_array_write_access_destroy = writeDestroy;
    core.godot_variant_new_pool_byte_array = variantNewArray;
    core.godot_variant_new_nil = variantNewNil;
    core.godot_print_error = printError;
    return core;
}
const godot_gdnative_core_api_struct core = makeCore();

// ---- Verve's allocations, failing at the N-th --------------------------------------------
struct Allocator {
    long count = 0, failAt = -1;
    static void* VERVE_CALL allocate(void* user, size_t size) {
        auto* self = static_cast<Allocator*>(user);
        return ++self->count == self->failAt ? nullptr : std::malloc(size);
    }
    static void VERVE_CALL release(void*, void* block) { std::free(block); }
};

verve_result saveAgent(const void* object, void* buffer, size_t* size) {
    return verve_agent_save_memory_binary(static_cast<const verve_agent*>(object), buffer, size);
}
verve_result saveBrain(const void* object, void* buffer, size_t* size) {
    return verve_brain_save_memory(static_cast<const verve_brain*>(object), buffer, size);
}
verve_result saveRecording(const void* object, void* buffer, size_t* size) {
    return verve_recording_save_memory(static_cast<const verve_recording*>(object), buffer, size);
}

class SaveToBytes : public ::testing::Test {
protected:
    void SetUp() override {
        vg_core = &core;
        fake = Fake{};
        verve_hooks hooks{};
        hooks.struct_size = VERVE_HOOKS_SIZE_V1;
        hooks.malloc_fn = &Allocator::allocate;
        hooks.free_fn = &Allocator::release;
        hooks.alloc_user = &allocator_;
        ASSERT_EQ(verve_set_hooks(&hooks), VERVE_OK) << verve_last_error();
        verve_agent_desc d;
        verve_agent_desc_default(&d);
        d.num_continuous_sensors = 2;
        d.num_actions = 3;
        d.planning = 1;
        ASSERT_EQ(verve_agent_create(&d, &agent_), VERVE_OK);
        ASSERT_EQ(verve_brain_create(&d, &brain_), VERVE_OK);
        ASSERT_EQ(verve_recording_create(agent_, &recording_), VERVE_OK) << verve_last_error();
        for (int i = 0; i < 40; ++i) {
            const float c[2] = {static_cast<float>(i % 7) / 7.0f, static_cast<float>(i % 5) / 5.0f};
            uint32_t action = 0;
            ASSERT_EQ(verve_agent_update(agent_, i % 6 == 0 ? 1.0f : 0.0f, nullptr, 0, c, 2, 0.1f, &action), VERVE_OK);
            ASSERT_EQ(verve_recording_add_step(recording_, 0.0f, nullptr, 0, c, 2, 0.1f, action), VERVE_OK);
        }
    }
    void TearDown() override {
        verve_agent_destroy(agent_);
        verve_brain_destroy(brain_);
        verve_recording_destroy(recording_);
        EXPECT_EQ(verve_set_hooks(nullptr), VERVE_OK) << verve_last_error();
    }
    // vg_save_to_bytes as a method would call it: the bytes, or "" and the error.
    bool save(vg_save_memory_fn fn, const void* object, std::vector<std::uint8_t>& out, std::string& error) {
        char lastError[VG_ERROR_SIZE] = "";
        vg_call c;
        if (!vg_begin_class(&c, vg_agent_class, lastError, "save_bytes", 0, nullptr, 0, 0)) return false;
        godot_variant v = vg_save_to_bytes(&c, fn, object);
        error = lastError;
        Variant& r = var(&v);
        if (r.type != GODOT_VARIANT_TYPE_POOL_BYTE_ARRAY) return false;
        out = *r.bytes;
        delete r.bytes;
        return true;
    }
    Allocator allocator_;
    verve_agent* agent_ = nullptr;
    verve_brain* brain_ = nullptr;
    verve_recording* recording_ = nullptr;
};

std::vector<std::uint8_t> direct(vg_save_memory_fn fn, const void* object) {
    size_t size = 0;
    EXPECT_EQ(fn(object, nullptr, &size), VERVE_OK);
    std::vector<std::uint8_t> bytes(size);
    EXPECT_EQ(fn(object, bytes.data(), &size), VERVE_OK);
    return bytes;
}

TEST_F(SaveToBytes, AnArrayThatCannotGrowIsAnErrorNotAWrongSizedSave) {
    std::vector<std::uint8_t> bytes;
    std::string error;
    ASSERT_TRUE(save(saveAgent, agent_, bytes, error)) << error;
    EXPECT_EQ(bytes, direct(saveAgent, agent_));
    fake.growFails = true;
    bytes.clear();
    EXPECT_FALSE(save(saveAgent, agent_, bytes, error)) << "returned " << bytes.size() << " bytes as a save";
    EXPECT_NE(error.find("out of memory"), std::string::npos) << error;
    EXPECT_FALSE(save(saveBrain, brain_, bytes, error));
    EXPECT_NE(error.find("out of memory"), std::string::npos) << error;
    EXPECT_FALSE(save(saveRecording, recording_, bytes, error));
    EXPECT_NE(error.find("out of memory"), std::string::npos) << error;
}

TEST_F(SaveToBytes, EveryFailedAllocationIsAnErrorAndTheNextSaveWorks) {
    for (const auto fn : {saveAgent, saveBrain, saveRecording}) {
        const void* object = fn == saveAgent   ? static_cast<const void*>(agent_)
                             : fn == saveBrain ? static_cast<const void*>(brain_)
                                               : static_cast<const void*>(recording_);
        const std::vector<std::uint8_t> reference = direct(fn, object);
        allocator_.count = 0;
        std::vector<std::uint8_t> bytes;
        std::string error;
        ASSERT_TRUE(save(fn, object, bytes, error)) << error;
        const long total = allocator_.count;
        ASSERT_GT(total, 0);
        for (long n = 1; n <= total; ++n) {
            allocator_.count = 0;
            allocator_.failAt = n;
            bytes.clear();
            const bool ok = save(fn, object, bytes, error);
            allocator_.failAt = -1;
            // Godot's own allocations are not Verve's: only a failure inside Verve is seen here.
            if (ok) {
                EXPECT_EQ(bytes, reference) << "N=" << n;
            } else {
                EXPECT_NE(error.find("OUT_OF_MEMORY"), std::string::npos) << "N=" << n << ": " << error;
            }
            ASSERT_TRUE(save(fn, object, bytes, error)) << "N=" << n << " then: " << error;
            ASSERT_EQ(bytes, reference) << "N=" << n;
        }
        RecordProperty(fn == saveAgent   ? "agentSaveAllocations"
                       : fn == saveBrain ? "brainSaveAllocations"
                                         : "recordingSaveAllocations",
                       static_cast<int>(total));
    }
}

}  // namespace
