// How `lancer render` shares one job among the processes mpirun started
// (docs/distributed.md). A still is cut into tiles that rank 0 hands out as
// processes ask for work and combines into the one film it writes; an
// animation's frames are handed out whole, each written by the process that
// rendered it. Rank 0 renders too, on a thread beside its coordinator.
//
// The MPI code lives in apps/mpi/ and is built only with LANCER_MPI; the
// render command sees this interface alone, and a process not started by
// mpirun never initialises MPI.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lancer/host/film.h"
#include "lancer/host/renderer.h"
#include "lancer/integrator.h"
#include "lancer/render_scene.h"

namespace lancer::app {

class Distribution {
  public:
    virtual ~Distribution() = default;

    virtual int rank() const = 0;
    virtual int processes() const = 0;
    // Rank 0 writes the still, the checkpoints and the progress display.
    bool coordinates() const { return rank() == 0; }

    // Every process calls this with the same scene, integrator and options.
    // On rank 0 `film` ends as the whole render (the samples each pixel
    // would have taken in one process, added in the same order) and the
    // stats cover every process; `on_progress` (rank 0) is called with the
    // film whenever a tile comes back, e.g. to checkpoint. On the others
    // `film` is scratch and the stats are theirs. options.cancel (rank 0)
    // ends the render at once, without waiting for the others.
    virtual RenderStats render_still(const RenderScene& scene, Integrator& integrator, const RenderOptions& options,
                                     Film& film, const std::function<void(const Film&)>& on_progress) = 0;

    // Renders `frames` (significant on rank 0 only), each by one process
    // through `render_frame(frame)`, which returns an exit status. Returns
    // 0, or the first failure's status (rank 0 also prints which frame and
    // process failed). `cancel` (rank 0) stops handing out frames.
    virtual int render_frames(const std::vector<int>& frames, const std::function<int(int frame)>& render_frame,
                              const std::atomic<bool>* cancel) = 0;

    // Ends the whole job now with `status` (a failing rank cannot leave the
    // others waiting for it).
    [[noreturn]] virtual void abort(int status) = 0;
};

// The job mpirun started this process in, or nullptr for a plain run (or
// mpirun -np 1). Empty `problem` unless the process cannot join its job
// (e.g. this lancer was built without MPI but runs under mpirun).
std::unique_ptr<Distribution> join_distributed_job(std::string& problem);

}  // namespace lancer::app
