// The settings `lancer trade` tries for each integrator, cheapest first,
// and the share of the time budget each integrator may spend on them.
#pragma once

#include <string>
#include <vector>

namespace lancer::app {

struct TradeSetting {
    std::string integrator;
    std::vector<std::string> parameters;  // key=value, as `lancer render -p`
    int samples_per_pixel = 1;
    // > 0: adaptive (`lancer render --noise`): each pixel stops when its
    // estimated relative error falls under this; samples_per_pixel is then
    // ignored and the cap comes from the reference.
    double noise_target = 0.0;
    // Relative cost (rays per pixel, roughly): the time of the next setting
    // is predicted from the last one's by the ratio of their costs.
    double cost = 1.0;

    // "n=64 spp=4": the parameters then the samples; "noise=0.05" when adaptive.
    std::string label() const;
    // "n64_spp4": the label as a file name.
    std::string slug() const;
};

// The ladder of one integrator, by increasing cost. `quick` keeps the
// short version (fewer, cheaper rungs).
std::vector<TradeSetting> trade_ladder(const std::string& integrator, bool quick);

// The fraction of the ladders' time budget one integrator may use;
// the noisy ones get most of it since they have the most to show.
double ladder_budget_share(const std::string& integrator);

}  // namespace lancer::app
