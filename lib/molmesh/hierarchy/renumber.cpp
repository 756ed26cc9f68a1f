#include "molmesh/hierarchy/renumber.hpp"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/cuthill_mckee_ordering.hpp>
#include <cstdlib>
#include <utility>

#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

std::vector<std::pair<int, int>> unique_edges(const TetMesh& mesh) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(mesh.tetrahedra.size() * 6);
  for (const auto& t : mesh.tetrahedra) {
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        const int u = t[static_cast<std::size_t>(a)], v = t[static_cast<std::size_t>(b)];
        edges.emplace_back(std::min(u, v), std::max(u, v));
      }
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace

std::vector<int> reverse_cuthill_mckee(const TetMesh& mesh) {
  using Graph =
      boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS,
                            boost::property<boost::vertex_color_t, boost::default_color_type,
                                            boost::property<boost::vertex_degree_t, int>>>;
  using Vertex = boost::graph_traits<Graph>::vertex_descriptor;
  Graph graph(mesh.points.size());
  for (const auto& [u, v] : unique_edges(mesh))
    boost::add_edge(static_cast<Vertex>(u), static_cast<Vertex>(v), graph);
  std::vector<Vertex> order(mesh.points.size());
  // Boost handles every connected component (isolated vertices included), starting each
  // from a pseudo-peripheral vertex; reverse iterators give the reverse ordering.
  boost::cuthill_mckee_ordering(graph, order.rbegin(), boost::get(boost::vertex_color, graph),
                                boost::make_degree_map(graph));
  std::vector<int> permutation(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) permutation[i] = static_cast<int>(order[i]);
  return permutation;
}

TetMesh permute_vertices(const TetMesh& mesh, const std::vector<int>& permutation) {
  if (permutation.size() != mesh.points.size()) {
    throw Error("vertex permutation has the wrong length");
  }
  std::vector<int> new_index(permutation.size(), -1);
  for (std::size_t i = 0; i < permutation.size(); ++i) {
    const int old = permutation[i];
    if (old < 0 || static_cast<std::size_t>(old) >= permutation.size() ||
        new_index[static_cast<std::size_t>(old)] != -1) {
      throw Error("vertex permutation is not a permutation");
    }
    new_index[static_cast<std::size_t>(old)] = static_cast<int>(i);
  }
  TetMesh out;
  out.points.resize(mesh.points.size());
  for (std::size_t i = 0; i < permutation.size(); ++i) {
    out.points[i] = mesh.points[static_cast<std::size_t>(permutation[i])];
  }
  if (mesh.vertex_markers.size() == mesh.points.size()) {
    out.vertex_markers.resize(mesh.points.size());
    for (std::size_t i = 0; i < permutation.size(); ++i) {
      out.vertex_markers[i] = mesh.vertex_markers[static_cast<std::size_t>(permutation[i])];
    }
  }
  out.tetrahedra = mesh.tetrahedra;
  for (auto& t : out.tetrahedra) {
    for (auto& v : t) v = new_index[static_cast<std::size_t>(v)];
  }
  out.boundary_faces = mesh.boundary_faces;
  for (auto& f : out.boundary_faces) {
    for (auto& v : f) v = new_index[static_cast<std::size_t>(v)];
  }
  out.cell_markers = mesh.cell_markers;
  out.boundary_face_markers = mesh.boundary_face_markers;
  return out;
}

TetMesh sort_cells_by_vertex(const TetMesh& mesh) {
  const std::size_t nt = mesh.tetrahedra.size();
  std::vector<std::pair<int, int>> key(nt);  // (lowest vertex, cell)
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& cell = mesh.tetrahedra[t];
    key[t] = {*std::min_element(cell.begin(), cell.end()), static_cast<int>(t)};
  }
  std::sort(key.begin(), key.end());
  TetMesh out = mesh;
  const bool has_markers = mesh.cell_markers.size() == nt;
  for (std::size_t t = 0; t < nt; ++t) {
    const auto old = static_cast<std::size_t>(key[t].second);
    out.tetrahedra[t] = mesh.tetrahedra[old];
    if (has_markers) out.cell_markers[t] = mesh.cell_markers[old];
  }
  return out;
}

int vertex_bandwidth(const TetMesh& mesh) {
  int bandwidth = 0;
  for (const auto& t : mesh.tetrahedra) {
    const auto [lo, hi] = std::minmax_element(t.begin(), t.end());
    bandwidth = std::max(bandwidth, *hi - *lo);
  }
  return bandwidth;
}

}  // namespace molmesh
