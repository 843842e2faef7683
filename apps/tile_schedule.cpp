#include "tile_schedule.h"

#include <algorithm>
#include <stdexcept>

namespace lancer::app {

TileSchedule::TileSchedule(const CropWindow& window, int tile_size)
    : m_window(window), m_tile_size(std::max(tile_size, 1)) {
    const int width = std::max(window.x1 - window.x0, 0), height = std::max(window.y1 - window.y0, 0);
    m_tiles_x = (width + m_tile_size - 1) / m_tile_size;
    const int tiles_y = (height + m_tile_size - 1) / m_tile_size;
    m_tiles.resize(std::size_t(m_tiles_x) * std::size_t(tiles_y));
}

int TileSchedule::tile_size_for(const CropWindow& window, int processes, int units_per_process) {
    const long long width = window.x1 - window.x0, height = window.y1 - window.y0;
    int size = 64;
    while (size > 8) {
        const long long tiles = ((width + size - 1) / size) * ((height + size - 1) / size);
        if (tiles >= (long long)(processes)*units_per_process) break;
        size /= 2;
    }
    return size;
}

CropWindow TileSchedule::tile_window(int tile) const {
    if (tile < 0 || tile >= tiles()) throw std::out_of_range("tile index out of range");
    const int tx = tile % m_tiles_x, ty = tile / m_tiles_x;
    const int x0 = m_window.x0 + tx * m_tile_size, y0 = m_window.y0 + ty * m_tile_size;
    return {x0, y0, std::min(x0 + m_tile_size, m_window.x1), std::min(y0 + m_tile_size, m_window.y1)};
}

void TileSchedule::begin_round(std::uint32_t target) {
    m_target = target;
    m_round.clear();
    m_cursor = 0;
    m_outstanding = 0;
    m_completed = 0;
    for (int tile = 0; tile < tiles(); ++tile) {
        const TileState& state = m_tiles[std::size_t(tile)];
        if (state.finished || state.least >= target) continue;
        m_round.push_back(tile);
    }
}

std::optional<TileUnit> TileSchedule::next() {
    if (m_cursor >= m_round.size()) return std::nullopt;
    ++m_outstanding;
    return TileUnit{m_round[m_cursor++], m_target};
}

void TileSchedule::completed(int tile, std::uint64_t samples_added, std::uint32_t least_samples,
                             std::uint32_t most_samples) {
    TileState& state = m_tiles.at(std::size_t(tile));
    state.least = least_samples;
    if (samples_added == 0 && most_samples < m_target) state.finished = true;
    if (m_outstanding > 0) --m_outstanding;
    ++m_completed;
}

int TileSchedule::unfinished() const {
    return int(std::count_if(m_tiles.begin(), m_tiles.end(), [](const TileState& s) { return !s.finished; }));
}

}  // namespace lancer::app
