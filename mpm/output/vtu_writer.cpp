// XML VTK unstructured grid with raw appended binary data (<AppendedData encoding="raw">, each
// array preceded by its UInt64 byte count; header_type="UInt64"): one vertex cell per particle,
// point data as the scene's `output.fields` ask. ParaView and VTK read it directly; it is ~10x
// faster to write than ASCII and about half the size. Fields: velocity [m/s], stress (6
// components xx yy zz xy yz xz) [Pa], plastic_strain [-], temperature [K], damage [-], mass [kg],
// volume [m^3], pressure [Pa], von_mises [Pa], material, object (indices).
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>

#include "mpm/output/atomic_file.hpp"
#include "mpm/output/output.hpp"

namespace impact::mpm {

namespace fs = std::filesystem;

SnapshotWriter::SnapshotWriter(const std::string& directory, std::vector<std::string> fields)
    : directory_(directory), fields_(std::move(fields)) {
  fs::create_directories(fs::path(directory_) / "particles");
}

namespace {

// One appended array: its XML header now, its bytes later (offsets in bytes from the "_").
class Appended {
 public:
  template <class T>
  void add(std::ostream& xml, const char* type, const char* name, int components,
           std::vector<T> data) {
    xml << "<DataArray type=\"" << type << "\"";
    if (name) xml << " Name=\"" << name << "\"";
    xml << " NumberOfComponents=\"" << components << "\" format=\"appended\" offset=\"" << offset_
        << "\"/>\n";
    const std::uint64_t bytes = data.size() * sizeof(T);
    std::string blob(sizeof bytes + bytes, '\0');
    std::memcpy(blob.data(), &bytes, sizeof bytes);
    std::memcpy(blob.data() + sizeof bytes, data.data(), bytes);
    offset_ += blob.size();
    blobs_.push_back(std::move(blob));
  }
  void write(std::ostream& o) const {
    o << "<AppendedData encoding=\"raw\">\n_";
    for (const auto& b : blobs_) o.write(b.data(), static_cast<std::streamsize>(b.size()));
    o << "\n</AppendedData>\n";
  }

 private:
  std::uint64_t offset_ = 0;
  std::vector<std::string> blobs_;
};

std::vector<double> scalar(std::size_t n, const std::function<double(std::size_t)>& f) {
  std::vector<double> v(n);
  for (std::size_t p = 0; p < n; ++p) v[p] = f(p);
  return v;
}

}  // namespace

void SnapshotWriter::write(const Particles& P, long step, double time) {
  char name[64];
  std::snprintf(name, sizeof name, "step_%06ld.vtu", step);
  const fs::path rel = fs::path("particles") / name;
  // The particles in play: those removed at the grid's edge (grid.outflow = remove) are not drawn.
  std::vector<std::size_t> in_play;
  in_play.reserve(P.size());
  for (std::size_t p = 0; p < P.size(); ++p)
    if (P.removed.empty() || !P.removed[p]) in_play.push_back(p);
  const std::size_t n = in_play.size();
  write_file_atomically(fs::path(directory_) / rel, [&](std::ostream& o) {
    Appended data;
    o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
         "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<UnstructuredGrid>\n"
         "<Piece NumberOfPoints=\""
      << n << "\" NumberOfCells=\"" << n << "\">\n<Points>\n";
    {
      std::vector<double> x(3 * n);
      for (std::size_t p = 0; p < n; ++p)
        for (int d = 0; d < 3; ++d) x[3 * p + d] = P.x[in_play[p]](d);
      data.add(o, "Float64", nullptr, 3, std::move(x));
    }
    o << "</Points>\n<Cells>\n";
    {
      std::vector<std::int64_t> conn(n), off(n);
      std::vector<std::uint8_t> types(n, 1);  // VTK_VERTEX
      for (std::size_t p = 0; p < n; ++p) {
        conn[p] = static_cast<std::int64_t>(p);
        off[p] = static_cast<std::int64_t>(p + 1);
      }
      data.add(o, "Int64", "connectivity", 1, std::move(conn));
      data.add(o, "Int64", "offsets", 1, std::move(off));
      data.add(o, "UInt8", "types", 1, std::move(types));
    }
    o << "</Cells>\n<PointData>\n";
    for (const std::string& f : fields_) {
      if (f == "velocity") {
        std::vector<double> v(3 * n);
        for (std::size_t p = 0; p < n; ++p)
          for (int d = 0; d < 3; ++d) v[3 * p + d] = P.v[in_play[p]](d);
        data.add(o, "Float64", "velocity", 3, std::move(v));
      } else if (f == "stress") {
        std::vector<double> v(6 * n);
        for (std::size_t p = 0; p < n; ++p) {
          const Mat3& s = P.state[in_play[p]].stress;
          const double c[6] = {s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(0, 2)};
          for (int d = 0; d < 6; ++d) v[6 * p + d] = c[d];
        }
        data.add(o, "Float64", "stress", 6, std::move(v));
      } else if (f == "plastic_strain") {
        data.add(o, "Float64", "plastic_strain", 1,
                 scalar(n, [&](std::size_t p) { return P.state[in_play[p]].plastic_strain; }));
      } else if (f == "temperature") {
        data.add(o, "Float64", "temperature", 1,
                 scalar(n, [&](std::size_t p) { return P.state[in_play[p]].temperature; }));
      } else if (f == "damage") {
        data.add(o, "Float64", "damage", 1,
                 scalar(n, [&](std::size_t p) { return P.state[in_play[p]].damage; }));
      } else if (f == "mass") {
        data.add(o, "Float64", "mass", 1,
                 scalar(n, [&](std::size_t p) { return P.mass[in_play[p]]; }));
      } else if (f == "volume") {
        data.add(o, "Float64", "volume", 1,
                 scalar(n, [&](std::size_t p) { return P.volume[in_play[p]]; }));
      } else if (f == "pressure") {
        data.add(o, "Float64", "pressure", 1,
                 scalar(n, [&](std::size_t p) { return -mean(P.state[in_play[p]].stress); }));
      } else if (f == "von_mises") {
        data.add(o, "Float64", "von_mises", 1,
                 scalar(n, [&](std::size_t p) { return von_mises(P.state[in_play[p]].stress); }));
      } else if (f == "material") {
        data.add(o, "Float64", "material", 1,
                 scalar(n, [&](std::size_t p) { return double(P.material[in_play[p]]); }));
      } else if (f == "object") {
        data.add(o, "Float64", "object", 1,
                 scalar(n, [&](std::size_t p) { return double(P.object[in_play[p]]); }));
      } else if (f == "field") {
        data.add(o, "Float64", "field", 1,
                 scalar(n, [&](std::size_t p) { return double(P.field[in_play[p]]); }));
      } else if (f == "failure_cause") {
        data.add(o, "Float64", "failure_cause", 1, scalar(n, [&](std::size_t p) {
                   return double(P.state[in_play[p]].failure_cause);
                 }));
      } else if (f == "failed_in_tension") {
        data.add(o, "Float64", "failed_in_tension", 1, scalar(n, [&](std::size_t p) {
                   return P.state[in_play[p]].failed_in_tension ? 1.0 : 0.0;
                 }));
      } else if (f == "instability") {
        data.add(o, "Float64", "instability", 1,
                 scalar(n, [&](std::size_t p) { return double(P.state[in_play[p]].instability); }));
      } else if (f == "failed") {
        data.add(o, "Float64", "failed", 1,
                 scalar(n, [&](std::size_t p) { return P.state[in_play[p]].failed ? 1.0 : 0.0; }));
      }
    }
    o << "</PointData>\n</Piece>\n</UnstructuredGrid>\n";
    data.write(o);
    o << "</VTKFile>\n";
  });

  // The collection lists only snapshots already renamed into place.
  entries_.emplace_back(time, rel.string());
  write_file_atomically(fs::path(directory_) / "particles.pvd", [&](std::ostream& pvd) {
    pvd.precision(17);
    pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
    for (const auto& [t, file] : entries_) {
      pvd << "<DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << file << "\"/>\n";
    }
    pvd << "</Collection>\n</VTKFile>\n";
  });
}

}  // namespace impact::mpm
