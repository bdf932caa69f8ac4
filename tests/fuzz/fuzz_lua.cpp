// libFuzzer target: the Lua module's entry points (Lua 5.4), driven without a script. Each input
// calls module functions and the methods of agents, brains and batches with arguments of any
// type: numbers (NaN, huge), strings, nested tables, and tables whose __index closes the agent,
// brain or batch mid-call (a use-after-free trap). A Lua error is the expected answer to bad
// arguments; a crash or sanitizer report is a bug.
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

const char* const kAgentMethods[] = {"update", "end_episode", "truncate_episode", "reset_short_term_memory",
                                     "set_learning", "learning", "set_action_selection", "action_selection",
                                     "action_probabilities", "descriptor", "value", "td_error", "rbf_count", "stats",
                                     "sample_values", "save_string", "save_binary_string", "close", "split_action",
                                     "join_action", "continuous_action"};
const char* const kBrainMethods[] = {"body", "rbf_count", "save_string", "save_binary_string", "close"};
const char* const kBatchMethods[] = {"update", "update", "update", "workers", "close"};
const char* const kFunctions[] = {"agent", "load_string", "defaults", "version", "brain", "load_brain_string", "batch"};
const char* const kDescriptorKeys[] = {"discrete", "continuous", "resolution", "actions", "allocation", "tau_value",
                                       "tau_discount", "planning", "curiosity", "seed", "circular", "kind",
                                       "index", "samples", "workers", "action_branches", "continuous_actions"};

// __index of a trap table: closes the agent, brain or batch kept as upvalue 1, then answers as
// upvalue 2 says: a plausible number, nil (no such field) or a list of two numbers (a sensor list),
// so that the reader goes on with what it read before the close.
int closingIndex(lua_State* L) {
    lua_pushvalue(L, lua_upvalueindex(1));
    if (lua_getfield(L, -1, "close") == LUA_TFUNCTION) {
        lua_pushvalue(L, -2);
        lua_pcall(L, 1, 0, 0);
    } else {
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    switch (lua_tointeger(L, lua_upvalueindex(2))) {
        case 1: lua_pushnil(L); break;
        case 2:
            lua_createtable(L, 2, 0);
            for (int i = 1; i <= 2; ++i) {
                lua_pushnumber(L, 0.5);
                lua_rawseti(L, -2, i);
            }
            break;
        default: lua_pushnumber(L, 0.5); break;
    }
    return 1;
}

enum Kind { kAgent, kBrain, kBatch, kKinds };

struct Driver {
    lua_State* L;
    FuzzedDataProvider& in;
    int refs[kKinds] = {LUA_NOREF, LUA_NOREF, LUA_NOREF};  // the agent, brain and batch most recently made

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
            case 4: {  // mostly the agent, now and then the brain or the batch where an agent belongs
                const int ref = refs[in.ConsumeIntegralInRange<int>(0, 7) == 0 ? in.ConsumeIntegralInRange<int>(1, 2) : kAgent];
                if (ref != LUA_NOREF) lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
                else lua_pushnil(L);
                break;
            }
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

    // A table that looks like an observation but closes the agent (or the brain or the batch) when
    // read.
    void pushTrap() {
        lua_newtable(L);
        lua_newtable(L);
        const int ref = refs[in.ConsumeIntegralInRange<int>(0, 3) == 0 ? in.ConsumeIntegralInRange<int>(1, 2) : kAgent];
        if (ref != LUA_NOREF) lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
        else lua_pushnil(L);
        lua_pushinteger(L, in.ConsumeIntegralInRange<int>(0, 2));
        lua_pushcclosure(L, closingIndex, 2);
        lua_setfield(L, -2, "__index");
        lua_setmetatable(L, -2);
        if (in.ConsumeBool()) {  // a length, so readers that ask for #t read its elements
            lua_pushinteger(L, in.ConsumeIntegralInRange<int>(1, 4));
            lua_setfield(L, -2, "n");
        }
    }

    // batch:update's arguments as a game passes them (so that some calls get past the checks): the
    // latest agent (or body) listed up to 4 times, rewards, observations of its two continuous
    // sensors (any element may be anything, a trap included), a dt and sometimes an actions table,
    // demonstrated actions and the continuous actions played.
    int pushCrowd() {
        const int n = in.ConsumeIntegralInRange<int>(0, 4);
        for (int list = 0; list < 3; ++list) {
            lua_createtable(L, n, 0);
            for (int i = 1; i <= n; ++i) {
                if (in.ConsumeIntegralInRange<int>(0, 15) == 0) {
                    pushValue(1);
                } else if (list == 2 && in.ConsumeIntegralInRange<int>(0, 7) == 0) {
                    pushTrap();
                } else if (list == 0) {
                    if (refs[kAgent] != LUA_NOREF) lua_rawgeti(L, LUA_REGISTRYINDEX, refs[kAgent]);
                    else lua_pushnil(L);
                } else if (list == 1) {
                    lua_pushnumber(L, in.ConsumeFloatingPointInRange<double>(-1.0, 1.0));
                } else {
                    lua_createtable(L, 0, 1);
                    lua_createtable(L, 2, 0);
                    for (int c = 1; c <= 2; ++c) {
                        lua_pushnumber(L, in.ConsumeFloatingPointInRange<double>(-1.0, 1.0));
                        lua_rawseti(L, -2, c);
                    }
                    lua_setfield(L, -2, "continuous");
                }
                lua_rawseti(L, -2, i);
            }
        }
        lua_pushnumber(L, in.ConsumeFloatingPointInRange<double>(0.001, 0.2));
        if (!in.ConsumeBool()) return 4;
        lua_newtable(L);
        if (in.ConsumeBool()) return 5;
        // Demonstrated actions (from 1, or false), then sometimes the continuous actions played:
        // per agent a list of 0-2 values (the first agent has none), or anything, a trap included.
        lua_createtable(L, n, 0);
        for (int i = 1; i <= n; ++i) {
            if (in.ConsumeIntegralInRange<int>(0, 15) == 0) pushValue(1);
            else if (in.ConsumeBool()) lua_pushboolean(L, 0);
            else lua_pushinteger(L, in.ConsumeIntegralInRange<int>(1, 3));
            lua_rawseti(L, -2, i);
        }
        if (in.ConsumeBool()) return 6;
        lua_createtable(L, n, 0);
        for (int i = 1; i <= n; ++i) {
            const int kind = in.ConsumeIntegralInRange<int>(0, 15);
            if (kind == 0) {
                pushValue(1);
            } else if (kind == 1) {
                pushTrap();
            } else {
                const int values = kind < 12 ? 0 : in.ConsumeIntegralInRange<int>(1, 2);
                lua_createtable(L, values, 0);
                for (int c = 1; c <= values; ++c) {
                    lua_pushnumber(L, in.ConsumeFloatingPointInRange<double>(-1.5, 1.5));
                    lua_rawseti(L, -2, c);
                }
            }
            lua_rawseti(L, -2, i);
        }
        return 7;
    }

    // Calls fn (on the stack top) with fuzzed arguments, protected, as a method of `self` (a kind)
    // or not (kKinds); keeps a returned agent, brain or batch.
    void call(int self, bool crowd) {
        const int base = lua_gettop(L) - 1;
        const bool method = self != kKinds;
        if (method) lua_rawgeti(L, LUA_REGISTRYINDEX, refs[self]);
        int args = 0;
        if (crowd) {
            args = pushCrowd();
        } else {
            args = in.ConsumeIntegralInRange<int>(0, 5);
            for (int i = 0; i < args; ++i) pushValue(0);
        }
        if (lua_pcall(L, args + (method ? 1 : 0), 1, 0) == LUA_OK && lua_isuserdata(L, -1)) {
            const Kind kind = kindOf(-1);
            if (refs[kind] != LUA_NOREF) luaL_unref(L, LUA_REGISTRYINDEX, refs[kind]);
            refs[kind] = luaL_ref(L, LUA_REGISTRYINDEX);
        }
        lua_settop(L, base);
    }

    // Which of the module's objects the value at idx is, told by a method only it has.
    Kind kindOf(int idx) {
        const int at = lua_absindex(L, idx);
        lua_getfield(L, at, "body");
        const bool brain = !lua_isnil(L, -1);
        lua_getfield(L, at, "workers");
        const bool batch = !lua_isnil(L, -1);
        lua_pop(L, 2);
        return brain ? kBrain : batch ? kBatch : kAgent;
    }

    void run() {
        lua_pushcfunction(L, luaopen_verve);
        if (lua_pcall(L, 0, 1, 0) != LUA_OK) return;
        const int module = lua_gettop(L);
        // A host's RBF budget, as in fuzz_calls: a descriptor table without max_rbfs gets 256 (for
        // an agent or a brain), so that an accepted agent is quick to build and save and a slow
        // input is a hang (a full lattice of a million RBFs, which the default budget allows, takes
        // 0.7 s to save without ASan). The size limits are fuzz_calls' and the unit tests' to check.
        if (luaL_dostring(L, "return function(verve) for _, name in ipairs{'agent', 'brain'} do local make = verve[name]\n"
                             "  verve[name] = function(d, ...)\n"
                             "    if type(d) == 'table' and rawget(d, 'max_rbfs') == nil then rawset(d, 'max_rbfs', 256) end\n"
                             "    return make(d, ...) end end end") != LUA_OK) {
            std::abort();
        }
        lua_pushvalue(L, module);
        lua_call(L, 1, 0);
        // A valid agent first, most of the time, so methods reach deep paths.
        if (in.ConsumeBool()) {
            luaL_dostring(L, "return function(verve) return verve.agent{continuous={{},{circular=true}}, actions=3} end");
            lua_pushvalue(L, module);
            if (lua_pcall(L, 1, 1, 0) == LUA_OK) refs[kAgent] = luaL_ref(L, LUA_REGISTRYINDEX);
            else lua_pop(L, 1);
        }
        for (int step = 0; step < 32 && in.remaining_bytes() > 0; ++step) {
            int self = in.ConsumeIntegralInRange<int>(0, 3) > 0 ? in.ConsumeIntegralInRange<int>(0, 5) % kKinds : kKinds;
            if (self != kKinds && refs[self] == LUA_NOREF) self = kKinds;
            const char* name = nullptr;
            if (self == kKinds) {
                name = in.PickValueInArray(kFunctions);
                lua_getfield(L, module, name);
            } else {
                name = self == kAgent ? in.PickValueInArray(kAgentMethods)
                       : self == kBrain ? in.PickValueInArray(kBrainMethods)
                                        : in.PickValueInArray(kBatchMethods);
                lua_rawgeti(L, LUA_REGISTRYINDEX, refs[self]);
                lua_getfield(L, -1, name);
                lua_remove(L, -2);
            }
            const bool crowd = self == kBatch && std::string(name) == "update" && in.ConsumeBool();
            if (lua_isfunction(L, -1)) call(self, crowd);
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
