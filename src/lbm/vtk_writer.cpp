#include "ship_lrm/lbm/vtk_writer.hpp"

#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace ship_lrm::lbm {

void write_vti(const std::string& path, const Lattice& lattice, const Fields& fields, double dx, const double origin[3]) {
  const std::size_t n = lattice.cells();
  if (fields.rho.size() != n || fields.u.size() != 3 * n) throw std::invalid_argument("write_vti: fields do not match the lattice");
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("write_vti: cannot open '" + path + "' for writing");
  const double o[3] = {origin ? origin[0] : 0.0, origin ? origin[1] : 0.0, origin ? origin[2] : 0.0};
  const std::uint64_t rho_bytes = n * sizeof(float), u_bytes = 3 * n * sizeof(float), flag_bytes = n;
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << "  <ImageData WholeExtent=\"0 " << lattice.nx() - 1 << " 0 " << lattice.ny() - 1 << " 0 " << lattice.nz() - 1 << "\" Origin=\""
      << o[0] << " " << o[1] << " " << o[2] << "\" Spacing=\"" << dx << " " << dx << " " << dx << "\">\n"
      << "    <Piece Extent=\"0 " << lattice.nx() - 1 << " 0 " << lattice.ny() - 1 << " 0 " << lattice.nz() - 1 << "\">\n"
      << "      <PointData Scalars=\"density\" Vectors=\"velocity\">\n"
      << "        <DataArray type=\"Float32\" Name=\"density\" format=\"appended\" offset=\"0\"/>\n"
      << "        <DataArray type=\"Float32\" Name=\"velocity\" NumberOfComponents=\"3\" format=\"appended\" offset=\"" << 8 + rho_bytes
      << "\"/>\n"
      << "        <DataArray type=\"UInt8\" Name=\"cell_type\" format=\"appended\" offset=\"" << 16 + rho_bytes + u_bytes << "\"/>\n"
      << "      </PointData>\n    </Piece>\n  </ImageData>\n  <AppendedData encoding=\"raw\">\n   _";
  out.write(reinterpret_cast<const char*>(&rho_bytes), 8);
  out.write(reinterpret_cast<const char*>(fields.rho.data()), static_cast<std::streamsize>(rho_bytes));
  out.write(reinterpret_cast<const char*>(&u_bytes), 8);
  out.write(reinterpret_cast<const char*>(fields.u.data()), static_cast<std::streamsize>(u_bytes));
  out.write(reinterpret_cast<const char*>(&flag_bytes), 8);
  std::vector<std::uint8_t> t(lattice.types());
  for (auto& v : t) v &= static_cast<std::uint8_t>(~kGeneralBit);
  out.write(reinterpret_cast<const char*>(t.data()), static_cast<std::streamsize>(flag_bytes));
  out << "\n  </AppendedData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error("write_vti: write to '" + path + "' failed");
}

}  // namespace ship_lrm::lbm
