#include "xdmf_writer.hpp"

#include <sstream>

#include "static_result_layout.hpp"

namespace catena::io {
namespace {

namespace layout = static_layout;

// How a dataset is stored, in XDMF's terms (NumberType + Precision in bytes).
struct XdmfNumber {
  const char* type;
  int precision;
};
constexpr XdmfNumber float64{"Float", 8};
constexpr XdmfNumber int64{"Int", 8};
constexpr XdmfNumber int32{"Int", 4};

// A reference to one HDF5 dataset: "<file>:<dataset>", with its shape ("rows columns").
class DataItemWriter {
 public:
  DataItemWriter(std::ostringstream& xml, std::string escaped_file_name)
      : xml_(xml), file_name_(std::move(escaped_file_name)) {}

  void write(const char* indent, const char* dataset, const std::string& dimensions,
             XdmfNumber number) const {
    xml_ << indent << "<DataItem Dimensions=\"" << dimensions << "\" NumberType=\"" << number.type
         << "\" Precision=\"" << number.precision << "\" Format=\"HDF\">" << file_name_ << ':'
         << dataset << "</DataItem>\n";
  }

 private:
  std::ostringstream& xml_;
  std::string file_name_;
};

}  // namespace

std::string xml_escaped(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      case '\'':
        escaped += "&apos;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

std::filesystem::path xdmf_path_for(const std::filesystem::path& hdf5_path) {
  std::filesystem::path xdmf_path = hdf5_path;
  xdmf_path.replace_extension(".xmf");
  return xdmf_path;
}

std::string static_result_xdmf(const XdmfStaticGrid& grid) {
  const std::string nodes = std::to_string(grid.n_nodes);
  const std::string elements = std::to_string(grid.n_elements);
  const std::string node_vectors = nodes + " 3";
  const std::string element_vectors = elements + " 3";
  const std::string connectivity = elements + " " + std::to_string(layout::nodes_per_element);

  std::ostringstream xml;
  const DataItemWriter data_item(xml, xml_escaped(grid.hdf5_file_name));
  const char* const item_indent = "        ";
  const auto attribute = [&](const char* name, const char* type, const char* center,
                             const char* dataset, const std::string& dimensions,
                             XdmfNumber number) {
    xml << "      <Attribute Name=\"" << name << "\" AttributeType=\"" << type << "\" Center=\""
        << center << "\">\n";
    data_item.write(item_indent, dataset, dimensions, number);
    xml << "      </Attribute>\n";
  };

  xml << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      << "<!-- " << layout::format
      << ": static solution on the deformed geometry; layout in Catena's docs/output.md -->\n"
      << "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"static\" GridType=\"Uniform\">\n"
      << "      <Topology TopologyType=\"Polyline\" NodesPerElement=\"" << layout::nodes_per_element
      << "\" NumberOfElements=\"" << elements << "\">\n";
  data_item.write(item_indent, layout::element_nodes, connectivity, int64);
  xml << "      </Topology>\n"
      << "      <Geometry GeometryType=\"XYZ\">\n";
  data_item.write(item_indent, layout::positions, node_vectors, float64);
  xml << "      </Geometry>\n";
  attribute("displacements", "Vector", "Node", layout::displacements, node_vectors, float64);
  attribute("slopes", "Vector", "Node", layout::slopes, node_vectors, float64);
  attribute("node_ids", "Scalar", "Node", layout::node_ids, nodes, int64);
  attribute("axial_force", "Scalar", "Cell", layout::axial_force, elements, float64);
  attribute("axial_strain", "Scalar", "Cell", layout::axial_strain, elements, float64);
  attribute("shear_force", "Vector", "Cell", layout::shear_force, element_vectors, float64);
  attribute("bending_moment", "Vector", "Cell", layout::bending_moment, element_vectors, float64);
  attribute("torsion", "Scalar", "Cell", layout::torsion, elements, float64);
  // Stored as int8 but announced as int32: the readers let HDF5 convert on reading, and
  // ParaView shows an 8-bit "Char" array as characters rather than as numbers to colour by.
  attribute("element_kind", "Scalar", "Cell", layout::element_kind, elements, int32);
  attribute("element_set", "Scalar", "Cell", layout::element_set, elements, int32);
  attribute("element_ids", "Scalar", "Cell", layout::element_ids, elements, int64);
  xml << "    </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";
  return xml.str();
}

}  // namespace catena::io
