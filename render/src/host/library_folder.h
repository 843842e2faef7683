// Where liblancer.so itself lies: the plugins and the image module are
// found relative to it, so an installed tree can be moved (internal to
// liblancer).
#pragma once

#include <string>

namespace lancer {

// The folder holding liblancer.so (canonical when it can be resolved);
// empty when the dynamic loader cannot say.
std::string folder_of_liblancer();

}  // namespace lancer
