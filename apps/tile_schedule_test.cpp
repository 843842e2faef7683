#include "tile_schedule.h"

#include <set>

#include <gtest/gtest.h>

namespace lancer::app {
namespace {

TEST(TileSchedule, TilesCoverTheWindowOnceWithSmallerEdgeTiles) {
    const CropWindow window{3, 2, 103, 52};  // 100 x 50
    TileSchedule schedule(window, 32);
    ASSERT_EQ(schedule.tiles(), 4 * 2);
    long long area = 0;
    for (int t = 0; t < schedule.tiles(); ++t) {
        const CropWindow tile = schedule.tile_window(t);
        EXPECT_GE(tile.x0, window.x0);
        EXPECT_LE(tile.x1, window.x1);
        EXPECT_GE(tile.y0, window.y0);
        EXPECT_LE(tile.y1, window.y1);
        area += (long long)(tile.x1 - tile.x0) * (tile.y1 - tile.y0);
    }
    EXPECT_EQ(area, 100 * 50);
    EXPECT_EQ(schedule.tile_window(3).x1 - schedule.tile_window(3).x0, 100 - 3 * 32);
}

TEST(TileSchedule, TileSizeShrinksUntilEveryProcessHasEnoughTiles) {
    EXPECT_EQ(TileSchedule::tile_size_for({0, 0, 1920, 1080}, 4, 6), 64);  // 30 x 17 tiles
    EXPECT_EQ(TileSchedule::tile_size_for({0, 0, 64, 48}, 3, 6), 8);       // 8 x 6 = 48 >= 18; 16 gives 12
    EXPECT_EQ(TileSchedule::tile_size_for({0, 0, 4, 4}, 8, 6), 8);         // never under 8
}

TEST(TileSchedule, AFixedRoundHandsOutEachTileOnceThenWaits) {
    TileSchedule schedule({0, 0, 40, 40}, 16);  // 3 x 3
    schedule.begin_round(16);
    std::set<int> seen;
    while (auto unit = schedule.next()) {
        EXPECT_EQ(unit->target, 16u);
        EXPECT_TRUE(seen.insert(unit->tile).second);
    }
    EXPECT_EQ(seen.size(), 9u);
    EXPECT_EQ(schedule.outstanding(), 9);
    EXPECT_FALSE(schedule.round_complete());
    for (int tile : seen) schedule.completed(tile, 100, 16, 16);
    EXPECT_TRUE(schedule.round_complete());
    EXPECT_DOUBLE_EQ(schedule.round_fraction_done(), 1.0);
}

TEST(TileSchedule, ARoundSkipsTilesAtTheTargetAndTilesThatAddedNothing) {
    TileSchedule schedule({0, 0, 48, 16}, 16);  // 3 tiles
    schedule.begin_round(4);
    schedule.completed(schedule.next()->tile, 64, 4, 4);  // reached 4
    schedule.completed(schedule.next()->tile, 32, 2, 4);  // stopped at 2 (deadline)
    schedule.completed(schedule.next()->tile, 16, 1, 4);
    schedule.begin_round(4);
    auto unit = schedule.next();
    ASSERT_TRUE(unit);
    EXPECT_EQ(unit->tile, 1);
    schedule.completed(1, 0, 2, 2);  // room everywhere, added nothing: finished
    unit = schedule.next();
    ASSERT_TRUE(unit);
    EXPECT_EQ(unit->tile, 2);
    schedule.completed(2, 0, 1, 4);  // added nothing, but a pixel had no room
    EXPECT_FALSE(schedule.next());
    EXPECT_EQ(schedule.unfinished(), 2);
    schedule.begin_round(8);
    EXPECT_EQ(schedule.next()->tile, 0);
    EXPECT_EQ(schedule.next()->tile, 2);
    EXPECT_FALSE(schedule.next());
}

}  // namespace
}  // namespace lancer::app
