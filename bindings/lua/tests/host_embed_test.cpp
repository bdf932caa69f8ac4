// A C++ host embedding Lua 5.4, as a game engine does: the engine owns the world and the frame
// loop, a Lua script (host_controller.lua) owns a Verve agent through `require "verve"`.
#include <gtest/gtest.h>

#include <lua.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

// One lua_State with the controller script loaded; every call goes through lua_pcall, so a Lua
// error becomes a C++ exception carrying the message and the state stays usable.
class LuaHost {
public:
    LuaHost() : L_(luaL_newstate()) {
        if (!L_) throw std::runtime_error("luaL_newstate failed");
        luaL_openlibs(L_);
        run("package.cpath = [[" VERVE_LUA_MODULE_DIR "/?.so]] "
            "package.path = [[" VERVE_LUA_SCRIPT_DIR "/?.lua]]");
        lua_getglobal(L_, "require");
        lua_pushstring(L_, "host_controller");
        check(lua_pcall(L_, 1, 1, 0));
        controller_ = luaL_ref(L_, LUA_REGISTRYINDEX);
    }
    ~LuaHost() { lua_close(L_); }  // collects the script's agents (their __gc frees them)
    LuaHost(const LuaHost&) = delete;
    LuaHost& operator=(const LuaHost&) = delete;

    void run(const char* code) { check(luaL_dostring(L_, code)); }

    void spawn(int seed) {
        push("spawn");
        lua_pushinteger(L_, seed);
        check(lua_pcall(L_, 1, 0, 0));
    }
    int think(double reward, double x, double dt) {
        push("think");
        lua_pushnumber(L_, reward);
        lua_pushnumber(L_, x);
        lua_pushnumber(L_, dt);
        check(lua_pcall(L_, 3, 1, 0));
        const auto action = static_cast<int>(lua_tointeger(L_, -1));
        lua_pop(L_, 1);
        return action;
    }
    void arrived(double reward) {
        push("arrived");
        lua_pushnumber(L_, reward);
        check(lua_pcall(L_, 1, 0, 0));
    }
    std::string save() {
        push("save");
        check(lua_pcall(L_, 0, 1, 0));
        size_t size = 0;
        const char* data = lua_tolstring(L_, -1, &size);
        std::string saved(data, size);
        lua_pop(L_, 1);
        return saved;
    }
    void restore(const std::string& saved) {
        push("restore");
        lua_pushlstring(L_, saved.data(), saved.size());
        check(lua_pcall(L_, 1, 0, 0));
    }

private:
    void push(const char* function) {
        lua_rawgeti(L_, LUA_REGISTRYINDEX, controller_);
        lua_getfield(L_, -1, function);
        lua_remove(L_, -2);
    }
    void check(int status) {
        if (status == LUA_OK) return;
        std::string message = lua_tostring(L_, -1) ? lua_tostring(L_, -1) : "(no message)";
        lua_pop(L_, 1);
        throw std::runtime_error(message);
    }

    lua_State* L_;
    int controller_ = LUA_NOREF;
};

// The engine's world: a body on cells 0..19 of a corridor, the exit at cell 19.
struct Corridor {
    static constexpr int kCells = 20;
    int cell = 0;
    double x() const { return -1.0 + 2.0 * cell / (kCells - 1); }
    bool move(int action) {  // 1 left, 2 right; true at the exit
        cell = std::max(0, std::min(kCells - 1, cell + (action == 2 ? 1 : -1)));
        return cell == kCells - 1;
    }
};

constexpr double kDt = 0.1;

// One trial driven by the script; the steps it took.
int runTrial(LuaHost& host, int maxSteps = 2000) {
    Corridor world;
    double reward = 0.0;
    for (int step = 1; step <= maxSteps; ++step) {
        if (world.move(host.think(reward, world.x(), kDt))) {
            host.arrived(1.0);
            return step;
        }
        // No per-step cost: with one, the critic can settle at the wall on V = cost / (1 - gamma),
        // where the TD error vanishes and the actor may stall (an actor-critic local optimum).
        reward = 0.0;
    }
    return maxSteps;
}

double meanTrials(LuaHost& host, int trials) {
    double sum = 0.0;
    for (int t = 0; t < trials; ++t) sum += runTrial(host);
    return sum / trials;
}

TEST(LuaHost, ScriptDrivenAgentLearnsTheEngineWorld) {
    LuaHost host;
    host.spawn(3);
    const double early = meanTrials(host, 5);
    meanTrials(host, 40);
    const double late = meanTrials(host, 10);
    EXPECT_LT(late, early / 2) << "early " << early << ", late " << late;
    EXPECT_LT(late, 30.0) << "the shortest path is 19 steps";
}

TEST(LuaHost, LibraryErrorsReachTheHostAndTheStateSurvives) {
    LuaHost host;
    host.spawn(1);
    try {
        host.think(0.0, std::numeric_limits<double>::quiet_NaN(), kDt);
        FAIL() << "a NaN observation was accepted";
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("verve: update: "), std::string::npos) << message;
        EXPECT_NE(message.find('['), std::string::npos) << "carries the result name: " << message;
    }
    EXPECT_THROW(host.think(0.0, 0.0, -1.0), std::runtime_error);
    const int action = host.think(0.0, 0.0, kDt);
    EXPECT_TRUE(action == 1 || action == 2);
}

TEST(LuaHost, SaveGameMovesAnAgentToAnotherState) {
    LuaHost original;
    original.spawn(5);
    meanTrials(original, 10);
    LuaHost restored;
    restored.restore(original.save());
    for (int step = 0; step < 500; ++step) {
        const double x = std::sin(step * 0.1);
        ASSERT_EQ(original.think(-0.1, x, kDt), restored.think(-0.1, x, kDt)) << "step " << step;
    }
}

TEST(LuaHost, ClosingTheStateCollectsLiveAgents) {
    LuaHost host;
    host.run("local verve = require 'verve' "
             "kept = {} "
             "for i = 1, 200 do kept[i] = verve.agent { discrete = { 8 }, actions = 3, seed = i } end "
             "for i = 1, 200 do kept[i]:update(0, { discrete = { i % 8 + 1 } }, 0.1) end");
    // ~LuaHost closes the state with 200 live agents: each __gc runs exactly once.
}

}  // namespace
