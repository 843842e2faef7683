// The verdict of `lancer trade` on measurements made up to show each case:
// Pareto fronts, the pick per budget, metrics that disagree and why, a
// setting that scored worse for more time, and the recommended command.
#include "trade_verdict.h"

#include <gtest/gtest.h>

#include "trade_report.h"

namespace lancer::app {
namespace {

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

TradeResult result(const std::string& integrator, const std::string& setting, double seconds, double rmse,
                   double rel_mse, double ssim, double estimated_rel_rmse) {
    TradeResult r;
    r.curve = r.integrator = integrator;
    r.setting = setting;
    r.seconds = seconds;
    r.rmse = rmse;
    r.rel_mse = rel_mse;
    r.ssim = ssim;
    r.estimated_rel_rmse = estimated_rel_rmse;
    r.spp = 1;
    return r;
}

// A room: whitted is fast, noise-free and dark (no indirect light), which
// SSIM forgives; path is noisy, converging to the reference.
TradeRun room() {
    TradeRun run;
    run.scene = "room.pov";
    run.width = 64;
    run.height = 48;
    run.reference.noise_rmse = 0.001;
    run.reference.noise_rel_mse = 0.0001;
    run.results.push_back(result("whitted", "spp=1", 0.01, 0.30, 0.50, 0.90, 0.0));
    TradeResult path4 = result("path", "spp=4", 0.04, 0.25, 0.20, 0.40, 0.42);
    path4.spp = 4;
    run.results.push_back(path4);
    TradeResult path64 = result("path", "spp=64", 0.64, 0.06, 0.012, 0.85, 0.10);
    path64.spp = 64;
    run.results.push_back(path64);
    TradeResult path256 = result("path", "spp=256", 2.56, 0.03, 0.011, 0.95, 0.05);
    path256.spp = 256;
    run.results.push_back(path256);
    TradeResult gather = result("gather", "n=16 spp=1", 0.5, 0.4, 0.9, 0.2, 0.8);
    gather.parameters = {"n=16"};
    run.results.push_back(gather);
    return run;
}

TEST(TradeVerdict, ParetoFrontKeepsOnlyWhatNothingBeats) {
    const TradeRun run = room();
    // By relative MSE: whitted, path 4, path 64, path 256; gather is beaten
    // by path 4 in both time and error.
    EXPECT_EQ(pareto_front(run, TradeMetric::RelMse), (std::vector<int>{0, 1, 2, 3}));
    // By 1 - SSIM, path 4 (0.60) loses to the faster whitted (0.10).
    EXPECT_EQ(pareto_front(run, TradeMetric::OneMinusSsim), (std::vector<int>{0, 3}));
}

TEST(TradeVerdict, EachBudgetGetsTheLowestErrorThatFits) {
    const TradeRun run = room();
    const TradeVerdict verdict = decide_trade(run);
    ASSERT_FALSE(verdict.budgets.empty());
    EXPECT_DOUBLE_EQ(verdict.budgets.front().budget_seconds, 0.01);
    EXPECT_DOUBLE_EQ(verdict.budgets.back().budget_seconds, 2.56);
    for (const BudgetVerdict& row : verdict.budgets)
        for (std::size_t m = 0; m < trade_metrics().size(); ++m) {
            ASSERT_GE(row.best[m], 0);
            const TradeResult& pick = run.results[row.best[m]];
            EXPECT_LE(pick.seconds, row.budget_seconds);
            for (const TradeResult& other : run.results) {
                if (other.seconds <= row.budget_seconds) {
                    EXPECT_LE(metric_error(pick, trade_metrics()[m]), metric_error(other, trade_metrics()[m]));
                }
            }
        }
    // All of the time: every metric picks path at 256 spp.
    EXPECT_TRUE(verdict.budgets.back().disagreement.empty());
    EXPECT_EQ(verdict.budgets.back().best, (std::vector<int>{3, 3, 3}));
}

TEST(TradeVerdict, SaysWhenAndWhyTheMetricsDisagree) {
    const TradeVerdict verdict = decide_trade(room());
    // At 0.04 s SSIM keeps whitted, the MSEs take path at 4 spp.
    const BudgetVerdict* at = nullptr;
    for (const BudgetVerdict& row : verdict.budgets)
        if (row.budget_seconds >= 0.04 && row.budget_seconds < 0.64) at = &row;
    ASSERT_NE(at, nullptr);
    EXPECT_CONTAINS(at->disagreement, "1 - SSIM picks whitted spp=1");
    EXPECT_CONTAINS(at->disagreement, "picks path spp=4");
    EXPECT_CONTAINS(at->disagreement, "whitted spp=1 is noise-free: its error is all bias");
    EXPECT_CONTAINS(at->disagreement, "(mostly noise)");
}

TEST(TradeVerdict, ATieIsNotADisagreement) {
    TradeRun run = room();
    // Path at 64 spp is now the better by RMSE, and ties path at 256
    // under relative MSE and SSIM: no disagreement worth a sentence.
    run.results[2].rmse = 0.02;
    run.results[2].ssim = 0.945;
    const TradeVerdict verdict = decide_trade(run);
    EXPECT_TRUE(verdict.budgets.back().disagreement.empty());
    EXPECT_TRUE(verdict.budgets.back().tie);
}

TEST(TradeVerdict, MoreTimeMoreErrorIsExplained) {
    TradeRun run = room();
    // --noise 0.1 took longer than --noise 0.2 and scored worse: its own
    // estimate (0.05) is far under the true relative RMSE (0.2).
    TradeResult loose = result("path", "noise=0.2", 1.0, 0.1, 0.02, 0.8, 0.12);
    TradeResult tight = result("path", "noise=0.1", 2.0, 0.12, 0.04, 0.78, 0.05);
    loose.curve = tight.curve = "path --noise";
    run.results.push_back(loose);
    run.results.push_back(tight);
    const TradeVerdict verdict = decide_trade(run);
    ASSERT_EQ(verdict.anomalies.size(), 1u);
    EXPECT_CONTAINS(verdict.anomalies[0], "path noise=0.1 (2 s) has a higher relative MSE");
    EXPECT_CONTAINS(verdict.anomalies[0], "than path noise=0.2");
    EXPECT_CONTAINS(verdict.anomalies[0], "estimated its own relative RMSE at 0.05 but measured 0.2");

    // Near the reference's own noise, the reference is to blame.
    run.reference.noise_rel_mse = 0.01;
    const TradeVerdict floor_verdict = decide_trade(run);
    ASSERT_EQ(floor_verdict.anomalies.size(), 1u);
    EXPECT_CONTAINS(floor_verdict.anomalies[0], "within 3x the reference's own noise");
}

TEST(TradeVerdict, RecommendsTheFastestSettingNearTheBest) {
    const TradeRun run = room();
    const TradeVerdict verdict = decide_trade(run);
    // path 64 (0.012) is within 25% of path 256 (0.011) at a quarter of the time.
    ASSERT_EQ(verdict.recommended, 2);
    EXPECT_EQ(verdict.recommended_command, "lancer render room.pov -i path --spp 64 --width 64 --height 48");
    EXPECT_CONTAINS(verdict.recommended_reason, "fastest setting within 25% of the lowest relative MSE");
}

TEST(TradeVerdict, CommandReproducesParametersAndNoiseTargets) {
    TradeResult gather = result("gather", "n=64 spp=4", 1.0, 0.1, 0.1, 0.9, 0.1);
    gather.parameters = {"n=64"};
    gather.spp = 4;
    EXPECT_EQ(render_options(gather), "-i gather -p n=64 --spp 4");
    TradeResult adaptive = result("path", "noise=0.05", 1.0, 0.1, 0.1, 0.9, 0.1);
    adaptive.noise_target = 0.05;
    adaptive.spp = 512;
    EXPECT_EQ(render_options(adaptive), "-i path --noise 0.05 --spp 512");
}

TEST(TradeVerdict, TheReportLeadsWithIt) {
    const TradeRun run = room();
    const std::string html = report_html(run, {});
    const std::size_t verdict = html.find("<h2>Verdict</h2>"), plots = html.find("<h2>Error against time</h2>");
    ASSERT_NE(verdict, std::string::npos);
    EXPECT_LT(verdict, plots);
    EXPECT_CONTAINS(html, "Recommended: <code>lancer render room.pov -i path --spp 64");
    EXPECT_CONTAINS(html, "SSIM compares local structure");
}

}  // namespace
}  // namespace lancer::app
