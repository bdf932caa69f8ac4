// libFuzzer target: the Lua module's entry points (Lua 5.4), driven without a script. Each input
// calls module functions and agent methods with arguments of any type: numbers (NaN, huge),
// strings, nested tables, and tables whose __index closes the agent mid-call (a use-after-free
// trap). A Lua error is the expected answer to bad arguments; a crash or sanitizer report is a bug.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdlib>
#include <string>

extern "C" {
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
int luaopen_verve(lua_State* L);
}

namespace {

const char* const kAgentMethods[] = {"update", "end_episode", "reset_short_term_memory", "set_learning", "learning",
                                     "descriptor", "value", "td_error", "rbf_count", "stats", "sample_values",
                                     "save_string", "close"};
const char* const kDescriptorKeys[] = {"discrete", "continuous", "resolution", "actions", "allocation", "tau_value",
                                       "tau_discount", "planning", "curiosity", "seed", "circular", "kind",
                                       "index", "samples"};

// __index of a trap table: closes the agent kept as upvalue 1, then answers a plausible number.
int closingIndex(lua_State* L) {
    lua_pushvalue(L, lua_upvalueindex(1));
    if (lua_getfield(L, -1, "close") == LUA_TFUNCTION) {
        lua_pushvalue(L, -2);
        lua_pcall(L, 1, 0, 0);
    } else {
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    lua_pushnumber(L, 0.5);
    return 1;
}

struct Driver {
    lua_State* L;
    FuzzedDataProvider& in;
    int agentRef = LUA_NOREF;  // the agent most recently made (registry reference)

    void pushNumber() {
        switch (in.ConsumeIntegralInRange<int>(0, 7)) {
            case 0: lua_pushnumber(L, NAN); break;
            case 1: lua_pushnumber(L, in.ConsumeBool() ? HUGE_VAL : -HUGE_VAL); break;
            case 2: lua_pushnumber(L, in.ConsumeFloatingPoint<double>()); break;
            case 3: lua_pushinteger(L, in.ConsumeIntegral<lua_Integer>()); break;
            default: lua_pushinteger(L, in.ConsumeIntegralInRange<lua_Integer>(-1, 12)); break;
        }
    }

    void pushValue(int depth) {
        switch (in.ConsumeIntegralInRange<int>(0, depth < 3 ? 7 : 3)) {
            case 0: lua_pushnil(L); break;
            case 1: lua_pushboolean(L, in.ConsumeBool()); break;
            case 2: {
                const std::string s = in.ConsumeRandomLengthString(64);
                lua_pushlstring(L, s.data(), s.size());
                break;
            }
            case 3: pushNumber(); break;
            case 4:
                if (agentRef != LUA_NOREF) lua_rawgeti(L, LUA_REGISTRYINDEX, agentRef);
                else lua_pushnil(L);
                break;
            case 5: pushTrap(); break;
            default: pushTable(depth + 1); break;
        }
    }

    // An array part and some named fields, any values.
    void pushTable(int depth) {
        lua_newtable(L);
        const int n = in.ConsumeIntegralInRange<int>(0, 6);
        for (int i = 1; i <= n; ++i) {
            pushValue(depth);
            lua_rawseti(L, -2, i);
        }
        const int named = in.ConsumeIntegralInRange<int>(0, 4);
        for (int i = 0; i < named; ++i) {
            lua_pushstring(L, in.PickValueInArray(kDescriptorKeys));
            pushValue(depth);
            lua_rawset(L, -3);
        }
    }

    // A table that looks like an observation but closes the agent when read.
    void pushTrap() {
        lua_newtable(L);
        lua_newtable(L);
        if (agentRef != LUA_NOREF) lua_rawgeti(L, LUA_REGISTRYINDEX, agentRef);
        else lua_pushnil(L);
        lua_pushcclosure(L, closingIndex, 1);
        lua_setfield(L, -2, "__index");
        lua_setmetatable(L, -2);
        if (in.ConsumeBool()) {  // a length, so readers that ask for #t read its elements
            lua_pushinteger(L, in.ConsumeIntegralInRange<int>(1, 4));
            lua_setfield(L, -2, "n");
        }
    }

    // Calls fn (on the stack top) with fuzzed arguments, protected; keeps a returned agent.
    void call(bool method) {
        const int base = lua_gettop(L) - 1;
        if (method) lua_rawgeti(L, LUA_REGISTRYINDEX, agentRef);
        const int args = in.ConsumeIntegralInRange<int>(0, 5);
        for (int i = 0; i < args; ++i) pushValue(0);
        if (lua_pcall(L, args + (method ? 1 : 0), 1, 0) == LUA_OK && lua_isuserdata(L, -1)) {
            if (agentRef != LUA_NOREF) luaL_unref(L, LUA_REGISTRYINDEX, agentRef);
            agentRef = luaL_ref(L, LUA_REGISTRYINDEX);
        }
        lua_settop(L, base);
    }

    void run() {
        lua_pushcfunction(L, luaopen_verve);
        if (lua_pcall(L, 0, 1, 0) != LUA_OK) return;
        const int module = lua_gettop(L);
        // A host's RBF budget, as in fuzz_calls: a descriptor table without max_rbfs gets 256, so
        // that an accepted agent is quick to build and save and a slow input is a hang (a full
        // lattice of a million RBFs, which the default budget allows, takes 0.7 s to save without
        // ASan). The size limits themselves are fuzz_calls' and the unit tests' to check.
        if (luaL_dostring(L, "return function(verve) local agent = verve.agent\n"
                             "  verve.agent = function(d, ...)\n"
                             "    if type(d) == 'table' and rawget(d, 'max_rbfs') == nil then rawset(d, 'max_rbfs', 256) end\n"
                             "    return agent(d, ...) end end") != LUA_OK) {
            std::abort();
        }
        lua_pushvalue(L, module);
        lua_call(L, 1, 0);
        // A valid agent first, most of the time, so methods reach deep paths.
        if (in.ConsumeBool()) {
            luaL_dostring(L, "return function(verve) return verve.agent{continuous={{},{circular=true}}, actions=3} end");
            lua_pushvalue(L, module);
            if (lua_pcall(L, 1, 1, 0) == LUA_OK) agentRef = luaL_ref(L, LUA_REGISTRYINDEX);
            else lua_pop(L, 1);
        }
        for (int step = 0; step < 32 && in.remaining_bytes() > 0; ++step) {
            const bool method = agentRef != LUA_NOREF && in.ConsumeIntegralInRange<int>(0, 3) > 0;
            if (method) {
                lua_rawgeti(L, LUA_REGISTRYINDEX, agentRef);
                lua_getfield(L, -1, in.PickValueInArray(kAgentMethods));
                lua_remove(L, -2);
            } else {
                static const char* const kFunctions[] = {"agent", "load_string", "defaults", "version"};
                lua_getfield(L, module, in.PickValueInArray(kFunctions));
            }
            if (lua_isfunction(L, -1)) call(method);
            else lua_pop(L, 1);
        }
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FuzzedDataProvider in(data, size);
    lua_State* L = luaL_newstate();
    luaL_openlibs(L);
    Driver{L, in}.run();
    lua_close(L);  // collects every agent (__gc)
    return 0;
}
