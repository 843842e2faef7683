// Which tile of a still a process renders next, and to how many samples,
// when the render is shared among processes (docs/distributed.md). Pure
// bookkeeping, no messaging: the MPI layer asks it for work and reports
// what came back.
//
// The image's render window is cut into square tiles. The render runs in
// rounds, each bringing every unfinished tile to a per-pixel target, and a
// round starts only when the previous one is complete, so the image refines
// evenly as one process's passes make it. A fixed sample count is one round
// to that count: a tile is rendered whole by one process, every pixel adds
// its samples in sample order, and the film is bit for bit the one-process
// film. A time budget or a noise target runs doubling rounds, as one
// process's passes double.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "lancer/host/renderer.h"

namespace lancer::app {

// A tile handed to a process: bring its pixels to `target` samples.
struct TileUnit {
    int tile = 0;
    std::uint32_t target = 0;
};

class TileSchedule {
  public:
    // `tile_size` pixels square; the last row and column may be smaller.
    TileSchedule(const CropWindow& window, int tile_size);

    // Edge length that gives at least `units_per_process` tiles per process
    // for a window, from 64 pixels down to 8.
    static int tile_size_for(const CropWindow& window, int processes, int units_per_process);

    int tiles() const { return int(m_tiles.size()); }
    CropWindow tile_window(int tile) const;

    // Starts a round to `target` samples per pixel: every tile that is not
    // finished and has a pixel under the target takes part.
    void begin_round(std::uint32_t target);
    // The next tile of this round, or none (all handed out).
    std::optional<TileUnit> next();
    // A unit's result: samples it added, the least and most counts of its
    // pixels. A tile that added nothing although every pixel had room under
    // the target is finished (with a noise target, every pixel stopped).
    void completed(int tile, std::uint64_t samples_added, std::uint32_t least_samples, std::uint32_t most_samples);
    // Tiles of this round handed out and not yet completed.
    int outstanding() const { return m_outstanding; }
    // Every tile of the round handed out and completed.
    bool round_complete() const { return m_outstanding == 0 && m_cursor >= m_round.size(); }
    // Share of this round's tiles that came back (1 for an empty round).
    double round_fraction_done() const { return m_round.empty() ? 1.0 : double(m_completed) / double(m_round.size()); }
    // Tiles not finished (some may have no work in the current round).
    int unfinished() const;
    // The least count a tile held when it last came back (0 before).
    std::uint32_t least_samples(int tile) const { return m_tiles[std::size_t(tile)].least; }

  private:
    struct TileState {
        std::uint32_t least = 0;
        bool finished = false;
    };
    CropWindow m_window;
    int m_tile_size;
    int m_tiles_x;
    std::vector<TileState> m_tiles;
    std::vector<int> m_round;  // tiles of the current round, in hand-out order
    std::size_t m_cursor = 0;
    std::uint32_t m_target = 0;
    int m_outstanding = 0;
    int m_completed = 0;  // tiles of this round that came back
};

}  // namespace lancer::app
