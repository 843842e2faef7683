// A plugin built for a future ABI: the host must refuse it by version
// before trusting anything else in the descriptor.
#include <lancer/integrator.h>

namespace {

const lancer::IntegratorDescriptor kDescriptor = {
    lancer::kPluginAbiVersion + 1000, "wrong_abi", "built for another ABI", nullptr, 0, nullptr,
};

}  // namespace

LANCER_EXPORT_INTEGRATOR(kDescriptor)
