#include "molmesh/tetmesh/tetgen_plc.hpp"

#include "molmesh/tetmesh/markers.hpp"

namespace molmesh::detail {

void fill_plc(const SurfaceMesh& surface, const SurfaceMesh& sphere,
              const std::vector<Sphere>& active_site, tetgenio& in) {
  const int n_surface = static_cast<int>(surface.points.size());
  const int n_in = n_surface + static_cast<int>(sphere.points.size());
  const int n_faces = static_cast<int>(surface.triangles.size() + sphere.triangles.size());
  in.firstnumber = 0;
  in.numberofpoints = n_in;
  in.pointlist = new REAL[static_cast<std::size_t>(n_in) * 3];
  for (int i = 0; i < n_in; ++i) {
    const Vec3& p = i < n_surface ? surface.points[i] : sphere.points[i - n_surface];
    for (int d = 0; d < 3; ++d) in.pointlist[3 * i + d] = p[d];
  }
  in.numberoffacets = n_faces;
  in.facetlist = new tetgenio::facet[static_cast<std::size_t>(n_faces)];
  in.facetmarkerlist = new int[static_cast<std::size_t>(n_faces)];
  for (int f = 0; f < n_faces; ++f) {
    const bool on_sphere = f >= static_cast<int>(surface.triangles.size());
    const Triangle& t =
        on_sphere ? sphere.triangles[f - surface.triangles.size()] : surface.triangles[f];
    const int offset = on_sphere ? n_surface : 0;
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3]{t[0] + offset, t[1] + offset, t[2] + offset};
    int marker = on_sphere ? markers::kOuterSphere : markers::kMolecularSurface;
    if (!on_sphere && !active_site.empty() &&
        markers::in_active_site(surface.points, t, active_site))
      marker = markers::kActiveSite;
    in.facetmarkerlist[f] = marker;
  }
}

}  // namespace molmesh::detail
