// Ray counting per thread slot: no shared cache line and no locked
// instruction on the hot path.
#include "lancer/host/counting_scene.h"

#include <algorithm>

#include <tbb/task_arena.h>

namespace lancer {
namespace {

// Slot 0 is shared by the threads that find no slot of their own and takes
// atomic adds; slots 1.. go to threads as they first count.
constexpr int kSharedSlot = 0;

// Each CountingScene's own number, so a thread's cached slot is never
// taken for that of a later scene built at the same address.
std::atomic<std::uint64_t> g_next_scene_id{1};

// The slot this thread counts into, for the scene numbered scene_id. In
// the initial-exec model (liblancer is loaded with the program), reading it
// is one load: the TBB thread index cost a call into libtbb per query.
struct ThreadSlot {
    std::uint64_t scene_id = 0;
    std::atomic<std::uint64_t>* count = nullptr;
};
thread_local ThreadSlot t_slot __attribute__((tls_model("initial-exec")));

}  // namespace

CountingScene::CountingScene(const RenderScene& inner)
    : m_inner(inner),
      m_slot_count(std::max(tbb::this_task_arena::max_concurrency(), 1) * 2 + 65),
      m_id(g_next_scene_id.fetch_add(1, std::memory_order_relaxed)) {
    m_slots = std::make_unique<Slot[]>(std::size_t(m_slot_count));
}

void CountingScene::count(std::uint64_t queries) const {
    ThreadSlot& mine = t_slot;
    if (mine.scene_id != m_id) {
        // A slot per thread (not per arena index: a thread may work in more
        // than one arena), taken only while some are left, so the counter
        // cannot wrap.
        int taken = m_slots_taken.load(std::memory_order_relaxed);
        while (taken + 1 < m_slot_count &&
               !m_slots_taken.compare_exchange_weak(taken, taken + 1, std::memory_order_relaxed)) {
        }
        mine.scene_id = m_id;
        mine.count = taken + 1 < m_slot_count ? &m_slots[taken + 1].count : nullptr;
    }
    if (mine.count) {
        mine.count->store(mine.count->load(std::memory_order_relaxed) + queries, std::memory_order_relaxed);
    } else {
        m_slots[kSharedSlot].count.fetch_add(queries, std::memory_order_relaxed);
    }
}

std::uint64_t CountingScene::rays() const {
    std::uint64_t total = 0;
    for (int i = 0; i < m_slot_count; ++i) total += m_slots[i].count.load(std::memory_order_relaxed);
    return total;
}

}  // namespace lancer
