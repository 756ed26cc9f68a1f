#include "molmesh/io/xdmf.hpp"

#include <sstream>

#include "molmesh/core/atomic_file.hpp"

namespace molmesh {
namespace {

void data_item(std::ostream& out, const std::string& indent, const std::string& dims,
               bool is_integer, const std::string& h5_reference, const std::string& dataset) {
  out << indent << "<DataItem Dimensions=\"" << dims << "\" NumberType=\""
      << (is_integer ? "Int" : "Float") << "\" Precision=\"" << (is_integer ? 4 : 8)
      << "\" Format=\"HDF\">" << h5_reference << ':' << dataset << "</DataItem>\n";
}

void grid(std::ostream& out, const std::string& indent, const std::string& h5_reference,
          const XdmfMesh& mesh) {
  const int per_cell = mesh.tetrahedra ? 4 : 3;
  out << indent << "<Grid Name=\"" << mesh.name << "\" GridType=\"Uniform\">\n";
  out << indent << "  <Topology TopologyType=\"" << (mesh.tetrahedra ? "Tetrahedron" : "Triangle")
      << "\" NumberOfElements=\"" << mesh.num_cells << "\">\n";
  data_item(out, indent + "    ", std::to_string(mesh.num_cells) + " " + std::to_string(per_cell),
            true, h5_reference, mesh.cells);
  out << indent << "  </Topology>\n";
  out << indent << "  <Geometry GeometryType=\"XYZ\">\n";
  data_item(out, indent + "    ", std::to_string(mesh.num_points) + " 3", false, h5_reference,
            mesh.points);
  out << indent << "  </Geometry>\n";
  for (const auto& attribute : mesh.attributes) {
    const auto count = attribute.on_cells ? mesh.num_cells : mesh.num_points;
    out << indent << "  <Attribute Name=\"" << attribute.name
        << "\" AttributeType=\"Scalar\" Center=\"" << (attribute.on_cells ? "Cell" : "Node")
        << "\">\n";
    data_item(out, indent + "    ", std::to_string(count), attribute.is_integer, h5_reference,
              attribute.dataset);
    out << indent << "  </Attribute>\n";
  }
  out << indent << "</Grid>\n";
}

}  // namespace

std::string xdmf_document(const std::string& h5_reference, const std::vector<XdmfMesh>& meshes,
                          bool as_collection) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n";
  if (as_collection) {
    // A spatial collection: ParaView shows one block per mesh, each can be toggled.
    out << "    <Grid Name=\"hierarchy\" GridType=\"Collection\" CollectionType=\"Spatial\">\n";
    for (const auto& mesh : meshes) grid(out, "      ", h5_reference, mesh);
    out << "    </Grid>\n";
  } else {
    for (const auto& mesh : meshes) grid(out, "    ", h5_reference, mesh);
  }
  out << "  </Domain>\n</Xdmf>\n";
  return out.str();
}

void write_xdmf(const std::filesystem::path& path, const std::string& h5_reference,
                const std::vector<XdmfMesh>& meshes, bool as_collection) {
  const auto text = xdmf_document(h5_reference, meshes, as_collection);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace molmesh
