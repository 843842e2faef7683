// Ray counting per TBB thread slot: no shared cache line and no locked
// instruction on the hot path.
#include "lancer/host/counting_scene.h"

#include <algorithm>

#include <tbb/task_arena.h>

namespace lancer {
namespace {

// Slot 0 is shared by threads outside any arena (index unknown) and takes
// atomic adds; slots 1.. belong to arena thread index 0.. .
constexpr int kSharedSlot = 0;

}  // namespace

CountingScene::CountingScene(const RenderScene& inner)
    : m_inner(inner), m_slot_count(std::max(tbb::this_task_arena::max_concurrency(), 1) * 2 + 65) {
    m_slots = std::make_unique<Slot[]>(std::size_t(m_slot_count));
}

void CountingScene::count(std::uint64_t queries) const {
    const int index = tbb::this_task_arena::current_thread_index();
    if (index >= 0 && index + 1 < m_slot_count) {
        std::atomic<std::uint64_t>& slot = m_slots[index + 1].count;
        slot.store(slot.load(std::memory_order_relaxed) + queries, std::memory_order_relaxed);
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
