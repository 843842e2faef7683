// What `lancer trade` concludes from its measurements: for each time
// budget the setting with the lowest error under each metric (read off the
// Pareto fronts of error against time), where the metrics disagree and
// why, settings that scored worse for more time, and one recommended
// command line. Pure: it reads a TradeRun and says nothing it did not
// measure.
#pragma once

#include <string>
#include <vector>

#include "trade_report.h"

namespace lancer::app {

// The three errors every result has; lower is better for each.
enum class TradeMetric { Rmse, RelMse, OneMinusSsim };
const std::vector<TradeMetric>& trade_metrics();
const char* metric_label(TradeMetric metric);  // "RMSE", "relative MSE", "1 - SSIM"
double metric_error(const TradeResult& result, TradeMetric metric);

// Indices into run.results of the settings no other setting beats in both
// time and error (cheapest first): the only ones worth running.
std::vector<int> pareto_front(const TradeRun& run, TradeMetric metric);

struct BudgetVerdict {
    double budget_seconds = 0.0;
    // Per trade_metrics(), the index of the lowest-error result that took
    // at most the budget (-1: none did).
    std::vector<int> best;
    // Empty when the metrics agree; else why they do not.
    std::string disagreement;
    // The metrics pick different settings whose errors tie (within 10%, or
    // the reference's noise): either is as good.
    bool tie = false;
};

struct TradeVerdict {
    std::vector<BudgetVerdict> budgets;  // doubling from the fastest render to the slowest
    // A costlier setting of one integrator that scored worse than a cheaper
    // one, with the reason the numbers give.
    std::vector<std::string> anomalies;
    int recommended = -1;  // index into run.results
    std::string recommended_command;
    std::string recommended_reason;
};

TradeVerdict decide_trade(const TradeRun& run);

// `lancer render` options that reproduce one result ("-i path --spp 16").
std::string render_options(const TradeResult& result);

}  // namespace lancer::app
