#include "scene_registry.hpp"

#include "cart_pole_scene.hpp"
#include "pendulum_scene.hpp"

namespace verve::scenes {

const std::vector<SceneInfo>& sceneRegistry() {
    static const std::vector<SceneInfo> registry{
        {"pendulum", "Bullet pendulum swing-up: 1 kg 1 m rod, torque +-2 N m, 20 s trials from a random state",
         [] { return std::make_unique<PendulumScene>(); }, 100, SceneMetric::RewardPerStep, false,
         {"angle (x 180 deg, 0 = upright)", "angular velocity (x 500 deg/s)"}},
        {"cart-pole", "Bullet cart-pole: 1 kg cart, 0.1 kg 1 m pole, force +-10 N, track +-2.4 m, pole +-12 deg",
         [] { return std::make_unique<CartPoleScene>(); }, 3000, SceneMetric::BalanceSeconds, true,
         {"cart x (x 2.4 m)", "cart velocity (x 2.4 m/s)", "pole angle (x 12 deg)",
          "pole angular velocity (x 100 deg/s)"}},
    };
    return registry;
}

const SceneInfo* findScene(const std::string& name) {
    for (const SceneInfo& s : sceneRegistry())
        if (s.name == name) return &s;
    return nullptr;
}

}  // namespace verve::scenes
