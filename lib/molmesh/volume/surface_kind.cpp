#include "molmesh/volume/surface_kind.hpp"

namespace molmesh {

std::string surface_kind_name(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::kGaussian:
      return "gaussian";
    case SurfaceKind::kVdw:
      return "vdw";
    case SurfaceKind::kSas:
      return "sas";
    case SurfaceKind::kSes:
      return "ses";
  }
  return "gaussian";
}

}  // namespace molmesh
