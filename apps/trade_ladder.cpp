// Ladders of settings for `lancer trade`.
#include "trade_ladder.h"

#include <cstdio>

namespace lancer::app {
namespace {

TradeSetting setting(const std::string& integrator, std::vector<std::string> parameters, int spp, double cost) {
    TradeSetting s;
    s.integrator = integrator;
    s.parameters = std::move(parameters);
    s.samples_per_pixel = spp;
    s.cost = cost * spp;
    return s;
}

}  // namespace

std::string TradeSetting::label() const {
    std::string text;
    for (const std::string& parameter : parameters) text += parameter + " ";
    if (noise_target > 0.0) {
        char target[32];
        std::snprintf(target, sizeof target, "noise=%g", noise_target);
        return text + target;
    }
    return text + "spp=" + std::to_string(samples_per_pixel);
}

std::string TradeSetting::slug() const {
    std::string text;
    for (char c : label()) {
        if (c == ' ')
            text += '_';
        else if (c == '.')
            text += 'p';
        else if (c != '=')
            text += c;
    }
    return text;
}

std::vector<TradeSetting> trade_ladder(const std::string& integrator, bool quick) {
    std::vector<TradeSetting> ladder;
    if (integrator == "raycast") {
        // Deterministic: more samples only antialias.
        for (int spp : {1, 4, 16}) ladder.push_back(setting(integrator, {}, spp, 1));
        if (quick) ladder.pop_back();
    } else if (integrator == "shadow") {
        // Hard shadows from proxies, then area lights sampled ever more finely.
        ladder.push_back(setting(integrator, {"area_samples=0"}, 1, 2));
        ladder.push_back(setting(integrator, {"area_samples=0"}, 4, 2));
        ladder.push_back(setting(integrator, {"area_samples=4"}, 4, 5));
        ladder.push_back(setting(integrator, {"area_samples=16"}, 4, 17));
        if (!quick) {
            ladder.push_back(setting(integrator, {"area_samples=16"}, 16, 17));
            ladder.push_back(setting(integrator, {"area_samples=64"}, 16, 65));
        }
    } else if (integrator == "whitted") {
        // Deeper recursion, then antialiasing at a depth that is enough
        // for everything but facing mirrors.
        for (int depth : {1, 2, 4, 8})
            ladder.push_back(setting(integrator, {"max_depth=" + std::to_string(depth)}, 1, 1 + depth * 0.5));
        ladder.push_back(setting(integrator, {"max_depth=8"}, 4, 5));
        if (!quick) ladder.push_back(setting(integrator, {"max_depth=8"}, 16, 5));
    } else if (integrator == "gather") {
        // Both knobs: directions per hit (n) and samples per pixel.
        ladder.push_back(setting(integrator, {"n=16"}, 1, 16));
        ladder.push_back(setting(integrator, {"n=16"}, 4, 16));
        ladder.push_back(setting(integrator, {"n=64"}, 4, 64));
        ladder.push_back(setting(integrator, {"n=64"}, 16, 64));
        if (!quick) {
            ladder.push_back(setting(integrator, {"n=128"}, 16, 128));
            ladder.push_back(setting(integrator, {"n=128"}, 64, 128));
            ladder.push_back(setting(integrator, {"n=128"}, 256, 128));
        }
    } else if (integrator == "path") {
        // Unbiased: only samples. Powers of 4 halve the noise at each rung.
        const int top = quick ? 256 : 4096;
        for (int spp = 1; spp <= top; spp *= quick ? 4 : 2) ladder.push_back(setting(integrator, {}, spp, 8));
    } else if (integrator == "path --noise") {
        // Adaptive sampling: what --noise buys over the same error at fixed
        // spp. The cost guess (as spp ~ 1/target²) only orders the rungs.
        for (double target : quick ? std::vector<double>{0.2, 0.1} : std::vector<double>{0.2, 0.1, 0.05, 0.025}) {
            TradeSetting s = setting("path", {}, 1, 8.0 / (target * target));
            s.noise_target = target;
            ladder.push_back(s);
        }
    }
    return ladder;
}

double ladder_budget_share(const std::string& integrator) {
    if (integrator == "raycast") return 0.05;
    if (integrator == "shadow") return 0.15;
    if (integrator == "whitted") return 0.10;
    if (integrator == "gather") return 0.30;
    if (integrator == "path") return 0.30;
    if (integrator == "path --noise") return 0.10;
    return 0.10;
}

}  // namespace lancer::app
