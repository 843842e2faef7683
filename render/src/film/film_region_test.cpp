// Film::restore_region: one tile's totals replaced, the rest untouched.
#include <vector>

#include <gtest/gtest.h>

#include "lancer/host/film.h"

namespace lancer {
namespace {

TEST(FilmRegion, RestoresOnlyTheRectangleAndKeepsTheNonfiniteTotal) {
    Film film(5, 4);
    film.add_sample(0, 0, Color(1.0f));
    film.add_sample(2, 1, Color(NAN));  // inside the region: replaced below
    ASSERT_EQ(film.nonfinite_samples(), 1u);
    std::vector<Film::Accumulator> tile(2 * 2);  // x 1..2, y 1..2
    tile[0].sum = glm::dvec3(6.0);
    tile[0].count = 3;
    tile[3].nonfinite = 2;
    film.restore_region(1, 1, 3, 3, tile.data());
    EXPECT_EQ(film.samples_taken(1, 1), 3u);
    EXPECT_FLOAT_EQ(film.mean(1, 1).r, 2.0f);
    EXPECT_EQ(film.samples_taken(2, 1), 0u);  // its NaN sample is gone
    EXPECT_EQ(film.samples_taken(2, 2), 2u);
    EXPECT_EQ(film.nonfinite_samples(), 2u);  // 1 - 1 + 2
    EXPECT_EQ(film.samples_taken(0, 0), 1u);  // outside: untouched
    EXPECT_TRUE(film.has_samples());
}

TEST(FilmRegion, RefusesARectangleOutsideTheFilm) {
    Film film(4, 4);
    std::vector<Film::Accumulator> tile(4);
    EXPECT_THROW(film.restore_region(3, 3, 5, 5, tile.data()), std::invalid_argument);
    EXPECT_THROW(film.restore_region(-1, 0, 1, 2, tile.data()), std::invalid_argument);
}

}  // namespace
}  // namespace lancer
