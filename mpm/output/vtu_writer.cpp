// XML VTK unstructured grid with raw appended binary data (<AppendedData encoding="raw">, each
// array preceded by its UInt64 byte count; header_type="UInt64"): one vertex cell per particle,
// point data as the scene's `output.fields` ask. ParaView and VTK read it directly; it is ~10x
// faster to write than ASCII and about half the size. Fields: mpm/particles/snapshot_fields.hpp
// (velocity [m/s], stress (6 components xx yy zz xy yz xz) [Pa], every other member of the
// particles' state, pressure [Pa], von_mises [Pa], material, object, field (indices), id (the
// seed index), ...). On several ranks each rank writes its own piece and rank 0 a .pvtu that names
// them (VTK's parallel unstructured grid): ParaView opens the step as one data set, and no rank
// ever holds another's particles.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "mpm/output/output.hpp"
#include "mpm/particles/snapshot_fields.hpp"
#include "support/atomic_file.hpp"

namespace impact::mpm {

namespace fs = std::filesystem;

SnapshotWriter::SnapshotWriter(const std::string& directory, std::vector<std::string> fields,
                               const Communicator& comm)
    : directory_(directory), fields_(std::move(fields)), comm_(comm) {
  if (root()) fs::create_directories(fs::path(directory_) / "particles");
  if (pieces()) comm_.barrier();  // the directory exists before any rank writes into it
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

// The number of components of an output field (the .pvtu declares them without the data).
int components(const std::string& field) {
  return find_snapshot_field(field)->components;
}

// Field `f` of the particles `in_play`, components() values per particle.
std::vector<double> field_values(const std::string& f, const Particles& P,
                                 const std::vector<std::size_t>& in_play) {
  const SnapshotField& field = *find_snapshot_field(f);  // the scene reader checked the name
  const auto c = static_cast<std::size_t>(field.components);
  std::vector<double> v(c * in_play.size());
  for (std::size_t i = 0; i < in_play.size(); ++i) field.values(P, in_play[i], &v[c * i]);
  return v;
}

// One .vtu of the particles P holds that are in play: those removed at the grid's edge
// (grid.outflow = remove) are not drawn.
void write_piece(const fs::path& path, const Particles& P, const std::vector<std::string>& fields) {
  std::vector<std::size_t> in_play;
  in_play.reserve(P.size());
  for (std::size_t p = 0; p < P.size(); ++p)
    if (P.removed.empty() || !P.removed[p]) in_play.push_back(p);
  const std::size_t n = in_play.size();
  write_file_atomically(path, [&](std::ostream& o) {
    Appended data;
    o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
         "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<UnstructuredGrid>\n"
         "<Piece NumberOfPoints=\""
      << n << "\" NumberOfCells=\"" << n << "\">\n<Points>\n";
    {
      std::vector<double> x(3 * n);
      for (std::size_t i = 0; i < n; ++i)
        for (int d = 0; d < 3; ++d) x[3 * i + d] = P.x[in_play[i]](d);
      data.add(o, "Float64", nullptr, 3, std::move(x));
    }
    o << "</Points>\n<Cells>\n";
    {
      std::vector<std::int64_t> conn(n), off(n);
      std::vector<std::uint8_t> types(n, 1);  // VTK_VERTEX
      for (std::size_t i = 0; i < n; ++i) {
        conn[i] = static_cast<std::int64_t>(i);
        off[i] = static_cast<std::int64_t>(i + 1);
      }
      data.add(o, "Int64", "connectivity", 1, std::move(conn));
      data.add(o, "Int64", "offsets", 1, std::move(off));
      data.add(o, "UInt8", "types", 1, std::move(types));
    }
    o << "</Cells>\n<PointData>\n";
    for (const std::string& f : fields)
      data.add(o, "Float64", f.c_str(), components(f), field_values(f, P, in_play));
    o << "</PointData>\n</Piece>\n</UnstructuredGrid>\n";
    data.write(o);
    o << "</VTKFile>\n";
  });
}

// The .pvtu of one step: the fields' names and components, and each rank's piece (paths relative
// to the .pvtu).
void write_parallel_index(const fs::path& path, const std::vector<std::string>& pieces,
                          const std::vector<std::string>& fields) {
  write_file_atomically(path, [&](std::ostream& o) {
    o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" "
         "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
         "<PUnstructuredGrid GhostLevel=\"0\">\n<PPoints>\n"
         "<PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n</PPoints>\n<PPointData>\n";
    for (const std::string& f : fields) {
      o << "<PDataArray type=\"Float64\" Name=\"" << f << "\" NumberOfComponents=\""
        << components(f) << "\"/>\n";
    }
    o << "</PPointData>\n";
    for (const std::string& piece : pieces) o << "<Piece Source=\"" << piece << "\"/>\n";
    o << "</PUnstructuredGrid>\n</VTKFile>\n";
  });
}

}  // namespace

void SnapshotWriter::write(const Particles& P, long step, double time) {
  char stem[64];
  std::snprintf(stem, sizeof stem, "step_%06ld", step);
  const fs::path dir = fs::path(directory_) / "particles";
  fs::path rel;
  if (!pieces()) {
    rel = fs::path("particles") / (std::string(stem) + ".vtu");
    write_piece(fs::path(directory_) / rel, P, fields_);
  } else {
    const auto piece = [&](int rank) {
      return std::string(stem) + "_rank" + std::to_string(rank) + ".vtu";
    };
    write_piece(dir / piece(comm_.rank()), P, fields_);
    comm_.barrier();  // every piece in place before the index names it
    rel = fs::path("particles") / (std::string(stem) + ".pvtu");
    if (root()) {
      std::vector<std::string> names;
      for (int r = 0; r < comm_.size(); ++r) names.push_back(piece(r));
      write_parallel_index(fs::path(directory_) / rel, names, fields_);
    }
  }
  // The collection lists only snapshots already renamed into place.
  entries_.emplace_back(time, rel.string());
  if (!root()) return;
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
