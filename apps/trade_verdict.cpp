// The verdict of `lancer trade`: see trade_verdict.h.
#include "trade_verdict.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace lancer::app {
namespace {

// Two errors closer than this share (or than the reference's own noise)
// are a tie: one seed per setting measures no finer.
constexpr double kTieShare = 0.10;
// The recommendation: the cheapest setting within this share of the lowest
// relative MSE measured.
constexpr double kGoodEnoughShare = 0.25;

std::string number(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

std::string name_of(const TradeResult& result) {
    return result.integrator + " " + result.setting;
}

std::string seconds_text(double seconds) {
    return number(seconds < 10.0 ? "%.2g s" : "%.0f s", seconds);
}

// The reference's own noise under a metric: errors below it are not measured.
double error_floor(const TradeRun& run, TradeMetric metric) {
    switch (metric) {
    case TradeMetric::Rmse: return run.reference.noise_rmse;
    case TradeMetric::RelMse: return run.reference.noise_rel_mse;
    case TradeMetric::OneMinusSsim: return 0.0;
    }
    return 0.0;
}

bool ties(const TradeRun& run, TradeMetric metric, const TradeResult& a, const TradeResult& b) {
    const double ea = metric_error(a, metric), eb = metric_error(b, metric);
    return std::abs(ea - eb) <= kTieShare * std::max(ea, eb) + error_floor(run, metric);
}

bool is_deterministic(const TradeResult& result) {
    return result.estimated_rel_rmse <= 0.0;
}

// "noise-free, so its error is all bias" or "its own noise estimate
// accounts for 80% of its relative MSE".
std::string error_kind(const TradeResult& result) {
    if (is_deterministic(result)) return name_of(result) + " is noise-free: its error is all bias";
    if (result.rel_mse <= 0.0) return name_of(result) + " matches the reference";
    const double noise_share = std::min(1.0, result.estimated_rel_rmse * result.estimated_rel_rmse / result.rel_mse);
    return name_of(result) + "'s own noise estimate accounts for " + number("%.0f%%", 100.0 * noise_share) +
           " of its relative MSE" + (noise_share > 0.5 ? " (mostly noise)" : " (mostly bias)");
}

// Why metric `a` prefers result `x` and metric `b` result `y`.
std::string why_metrics_differ(TradeMetric a, TradeMetric b, const TradeResult& x, const TradeResult& y) {
    const bool ssim = a == TradeMetric::OneMinusSsim || b == TradeMetric::OneMinusSsim;
    std::string text;
    if (ssim)
        text =
            "SSIM compares local structure in sRGB luma: it forgives an error that is smooth across the image "
            "(a bias such as missing indirect light) and punishes pixel noise, while the MSEs add up every "
            "pixel's squared error whatever its kind. ";
    else
        text =
            "RMSE, in linear RGB, is decided by the brightest pixels (lights, highlights); relative MSE divides "
            "each pixel's error by its brightness, so dark regions (shadows, indirect light) weigh as much as "
            "bright ones: " +
            name_of(a == TradeMetric::Rmse ? x : y) + " is closer in the bright parts, " +
            name_of(a == TradeMetric::Rmse ? y : x) + " in the dark ones. ";
    return text + "Here " + error_kind(x) + "; " + error_kind(y) + ".";
}

std::vector<double> budget_ladder(const TradeRun& run) {
    double fastest = 0.0, slowest = 0.0;
    for (const TradeResult& r : run.results) {
        fastest = fastest == 0.0 ? r.seconds : std::min(fastest, r.seconds);
        slowest = std::max(slowest, r.seconds);
    }
    std::vector<double> budgets;
    if (run.results.empty()) return budgets;
    for (double b = std::max(fastest, 1e-6); b < slowest; b *= 2.0) budgets.push_back(b);
    // The slowest render closes the ladder, in place of a step just below it.
    if (budgets.size() > 1 && budgets.back() * 1.25 > slowest) budgets.pop_back();
    budgets.push_back(slowest);
    return budgets;
}

BudgetVerdict verdict_at(const TradeRun& run, double budget) {
    BudgetVerdict verdict;
    verdict.budget_seconds = budget;
    for (TradeMetric metric : trade_metrics()) {
        int best = -1;
        for (int i = 0; i < int(run.results.size()); ++i) {
            const TradeResult& r = run.results[i];
            if (r.seconds > budget) continue;
            if (best < 0 || metric_error(r, metric) < metric_error(run.results[best], metric)) best = i;
        }
        verdict.best.push_back(best);
    }
    // The first pair of metrics whose winners differ beyond a tie.
    const std::vector<TradeMetric>& metrics = trade_metrics();
    for (std::size_t a = 0; a < metrics.size() && verdict.disagreement.empty(); ++a)
        for (std::size_t b = a + 1; b < metrics.size() && verdict.disagreement.empty(); ++b) {
            const int x = verdict.best[a], y = verdict.best[b];
            if (x < 0 || y < 0 || x == y) continue;
            const TradeResult &rx = run.results[x], &ry = run.results[y];
            if (ties(run, metrics[a], rx, ry) || ties(run, metrics[b], rx, ry)) {
                verdict.tie = true;
                continue;
            }
            verdict.disagreement = std::string(metric_label(metrics[a])) + " picks " + name_of(rx) + ", " +
                                   metric_label(metrics[b]) + " picks " + name_of(ry) + ". " +
                                   why_metrics_differ(metrics[a], metrics[b], rx, ry);
        }
    if (!verdict.disagreement.empty()) verdict.tie = false;
    return verdict;
}

// Within one curve, a setting that took longer and scored worse (beyond a
// tie) than a cheaper one, under relative MSE.
std::vector<std::string> find_anomalies(const TradeRun& run) {
    std::vector<std::string> found;
    const double floor = error_floor(run, TradeMetric::RelMse);
    for (std::size_t j = 0; j < run.results.size(); ++j) {
        const TradeResult& costly = run.results[j];
        int cheaper = -1;
        for (std::size_t i = 0; i < run.results.size(); ++i) {
            const TradeResult& r = run.results[i];
            if (i == j || r.curve != costly.curve || r.seconds >= costly.seconds) continue;
            if (cheaper < 0 || r.rel_mse < run.results[cheaper].rel_mse) cheaper = int(i);
        }
        if (cheaper < 0) continue;
        const TradeResult& cheap = run.results[cheaper];
        if (costly.rel_mse <= cheap.rel_mse * (1.0 + kTieShare) + floor) continue;
        std::string text = name_of(costly) + " (" + seconds_text(costly.seconds) + ") has a higher relative MSE (" +
                           number("%.3g", costly.rel_mse) + ") than " + name_of(cheap) + " (" +
                           seconds_text(cheap.seconds) + ", " + number("%.3g", cheap.rel_mse) + "). ";
        const double true_rel_rmse = std::sqrt(costly.rel_mse);
        if (cheap.rel_mse < 3.0 * floor) {
            text += "Both are within 3x the reference's own noise (relative MSE " + number("%.3g", floor) +
                    "): the reference, not the render, sets these scores; a larger --budget makes a cleaner "
                    "reference that can tell them apart.";
        } else if (!is_deterministic(costly) && costly.estimated_rel_rmse < 0.7 * true_rel_rmse) {
            text += "It estimated its own relative RMSE at " + number("%.3g", costly.estimated_rel_rmse) +
                    " but measured " + number("%.3g", true_rel_rmse) +
                    ": its error is mostly what the per-pixel estimate cannot see (rare bright paths, "
                    "fireflies), which one seed decides; rerun with another --seed to see the spread.";
        } else if (is_deterministic(costly)) {
            text +=
                "Its error is bias, which more of this setting does not lower: the setting changes what is "
                "computed, not how precisely.";
        } else {
            text +=
                "One seed each: the difference is within what another --seed would change (their own noise "
                "estimates are " +
                number("%.3g", cheap.estimated_rel_rmse) + " and " + number("%.3g", costly.estimated_rel_rmse) + ").";
        }
        found.push_back(text);
    }
    return found;
}

std::string quoted(const std::string& text) {
    if (text.find_first_of(" '\"\\$`") == std::string::npos) return text;
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

}  // namespace

const std::vector<TradeMetric>& trade_metrics() {
    static const std::vector<TradeMetric> all{TradeMetric::Rmse, TradeMetric::RelMse, TradeMetric::OneMinusSsim};
    return all;
}

const char* metric_label(TradeMetric metric) {
    switch (metric) {
    case TradeMetric::Rmse: return "RMSE";
    case TradeMetric::RelMse: return "relative MSE";
    case TradeMetric::OneMinusSsim: return "1 - SSIM";
    }
    return "?";
}

double metric_error(const TradeResult& result, TradeMetric metric) {
    switch (metric) {
    case TradeMetric::Rmse: return result.rmse;
    case TradeMetric::RelMse: return result.rel_mse;
    case TradeMetric::OneMinusSsim: return 1.0 - result.ssim;
    }
    return 0.0;
}

std::vector<int> pareto_front(const TradeRun& run, TradeMetric metric) {
    std::vector<int> order(run.results.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        const TradeResult &ra = run.results[a], &rb = run.results[b];
        if (ra.seconds != rb.seconds) return ra.seconds < rb.seconds;
        return metric_error(ra, metric) < metric_error(rb, metric);
    });
    std::vector<int> front;
    for (int i : order)
        if (front.empty() || metric_error(run.results[i], metric) < metric_error(run.results[front.back()], metric))
            front.push_back(i);
    return front;
}

std::string render_options(const TradeResult& result) {
    std::string options = "-i " + result.integrator;
    for (const std::string& parameter : result.parameters) options += " -p " + parameter;
    if (result.noise_target > 0.0) options += " --noise " + number("%g", result.noise_target);
    options += " --spp " + std::to_string(result.spp);
    return options;
}

TradeVerdict decide_trade(const TradeRun& run) {
    TradeVerdict verdict;
    for (double budget : budget_ladder(run)) verdict.budgets.push_back(verdict_at(run, budget));
    verdict.anomalies = find_anomalies(run);
    if (run.results.empty()) return verdict;

    int lowest = 0;
    for (int i = 1; i < int(run.results.size()); ++i)
        if (run.results[i].rel_mse < run.results[lowest].rel_mse) lowest = i;
    const double good_enough =
        run.results[lowest].rel_mse * (1.0 + kGoodEnoughShare) + error_floor(run, TradeMetric::RelMse);
    for (int i = 0; i < int(run.results.size()); ++i) {
        const TradeResult& r = run.results[i];
        if (r.rel_mse <= good_enough &&
            (verdict.recommended < 0 || r.seconds < run.results[verdict.recommended].seconds))
            verdict.recommended = i;
    }
    const TradeResult& pick = run.results[verdict.recommended];
    verdict.recommended_command = "lancer render " + quoted(run.scene) + " " + render_options(pick) + " --width " +
                                  std::to_string(run.width) + " --height " + std::to_string(run.height) +
                                  (run.seed ? " --seed " + std::to_string(run.seed) : std::string());
    verdict.recommended_reason =
        name_of(pick) + " (" + seconds_text(pick.seconds) + ", relative MSE " + number("%.3g", pick.rel_mse) +
        ") is the fastest setting within " + number("%.0f%%", 100.0 * kGoodEnoughShare) +
        " of the lowest relative MSE measured (" + number("%.3g", run.results[lowest].rel_mse) + ", " +
        name_of(run.results[lowest]) + " in " + seconds_text(run.results[lowest].seconds) +
        "). Relative MSE decides because it counts dark and bright regions alike and is what --noise steers by.";
    return verdict;
}

}  // namespace lancer::app
