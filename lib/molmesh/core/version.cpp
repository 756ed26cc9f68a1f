#include "molmesh/core/version.hpp"

namespace molmesh {

const char* version() { return MOLMESH_VERSION; }

}  // namespace molmesh
