// The ship-wake table in HDF5 (see wake_table.hpp), through the HDF5 C library.
#include <hdf5.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <future>
#include <mutex>

#include "ship_lrm/wake/wake_table.hpp"

namespace ship_lrm::wake {
namespace {
// Debian's HDF5 is the serial build, which is not thread-safe: every HDF5 call in this file runs
// under this one process-wide lock (the ROS nodelets share a process and open tables from several
// threads). Recursive: public functions that hold it call each other.
std::recursive_mutex& hdf5_mutex() {
  static std::recursive_mutex m;
  return m;
}
using Hdf5Lock = std::lock_guard<std::recursive_mutex>;
}  // namespace

namespace {

// Closes an HDF5 handle when it goes out of scope.
struct Handle {
  hid_t id = -1;
  herr_t (*close)(hid_t) = nullptr;
  Handle() = default;
  Handle(hid_t i, herr_t (*c)(hid_t)) : id(i), close(c) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& o) noexcept : id(o.id), close(o.close) { o.id = -1; }
  Handle& operator=(Handle&& o) noexcept {
    reset();
    id = o.id;
    close = o.close;
    o.id = -1;
    return *this;
  }
  ~Handle() { reset(); }
  void reset() {
    if (id >= 0 && close) close(id);
    id = -1;
  }
  operator hid_t() const { return id; }
};

void quiet() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }  // our messages instead of HDF5's stack dumps

void ok(herr_t e, const std::string& what) {
  if (e < 0) throw TableError("wake table: " + what + " failed");
}

// IEEE 754 binary16 on disk (HDF5 1.10 has no predefined half type; the recipe h5py uses).
Handle half_type() {
  Handle t(H5Tcopy(H5T_IEEE_F32LE), H5Tclose);
  ok(H5Tset_fields(t, 15, 10, 5, 0, 10), "float16 type");
  ok(H5Tset_size(t, 2), "float16 type");
  ok(H5Tset_ebias(t, 15), "float16 type");
  return t;
}

void write_attr(hid_t obj, const char* name, const std::vector<double>& v) {
  const hsize_t n = v.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  if (H5Aexists(obj, name) > 0) H5Adelete(obj, name);
  Handle a(H5Acreate2(obj, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  ok(H5Awrite(a, H5T_NATIVE_DOUBLE, v.data()), std::string("writing attribute ") + name);
}

void write_attr(hid_t obj, const char* name, const std::string& s) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, std::max<std::size_t>(1, s.size()));
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (H5Aexists(obj, name) > 0) H5Adelete(obj, name);
  Handle a(H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  ok(H5Awrite(a, type, s.empty() ? " " : s.data()), std::string("writing attribute ") + name);
}

std::vector<double> read_attr_numbers(hid_t obj, const char* name, std::size_t expected, const std::string& path) {
  if (H5Aexists(obj, name) <= 0) throw TableError("wake table '" + path + "': attribute '" + name + "' is missing");
  Handle a(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose);
  Handle space(H5Aget_space(a), H5Sclose);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  if (n != static_cast<hssize_t>(expected))
    throw TableError("wake table '" + path + "': attribute '" + name + "' has " + std::to_string(n) + " values, expected " +
                     std::to_string(expected));
  std::vector<double> v(expected);
  if (H5Aread(a, H5T_NATIVE_DOUBLE, v.data()) < 0) throw TableError("wake table '" + path + "': attribute '" + name + "' is unreadable");
  for (double x : v)
    if (!std::isfinite(x)) throw TableError("wake table '" + path + "': attribute '" + name + "' is not finite");
  return v;
}

std::string read_attr_string(hid_t obj, const char* name, const std::string& path) {
  if (H5Aexists(obj, name) <= 0) throw TableError("wake table '" + path + "': attribute '" + name + "' is missing");
  Handle a(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose);
  Handle type(H5Aget_type(a), H5Tclose);
  if (H5Tget_class(type) != H5T_STRING) throw TableError("wake table '" + path + "': attribute '" + name + "' is not a string");
  std::string s(H5Tget_size(type), '\0');
  if (H5Aread(a, type, s.data()) < 0) throw TableError("wake table '" + path + "': attribute '" + name + "' is unreadable");
  while (!s.empty() && (s.back() == '\0' || s.back() == ' ')) s.pop_back();
  return s;
}

// Reads or writes the box [lo, lo + n) (x, y, z) of one frame of /velocity and /density.
bool frame_box(hid_t vel, hid_t rho, bool write, hsize_t frame, const std::array<int, 3>& lo, const std::array<int, 3>& n, float* u,
               float* r) {
  const hsize_t sv[5] = {frame, hsize_t(lo[2]), hsize_t(lo[1]), hsize_t(lo[0]), 0},
                cv[5] = {1, hsize_t(n[2]), hsize_t(n[1]), hsize_t(n[0]), 3};
  const hsize_t sr[4] = {frame, hsize_t(lo[2]), hsize_t(lo[1]), hsize_t(lo[0])}, cr[4] = {1, hsize_t(n[2]), hsize_t(n[1]), hsize_t(n[0])};
  Handle fsv(H5Dget_space(vel), H5Sclose), fsr(H5Dget_space(rho), H5Sclose);
  if (H5Sselect_hyperslab(fsv, H5S_SELECT_SET, sv, nullptr, cv, nullptr) < 0 ||
      H5Sselect_hyperslab(fsr, H5S_SELECT_SET, sr, nullptr, cr, nullptr) < 0)
    return false;
  Handle msv(H5Screate_simple(5, cv, nullptr), H5Sclose), msr(H5Screate_simple(4, cr, nullptr), H5Sclose);
  if (write)
    return H5Dwrite(vel, H5T_NATIVE_FLOAT, msv, fsv, H5P_DEFAULT, u) >= 0 && H5Dwrite(rho, H5T_NATIVE_FLOAT, msr, fsr, H5P_DEFAULT, r) >= 0;
  return H5Dread(vel, H5T_NATIVE_FLOAT, msv, fsv, H5P_DEFAULT, u) >= 0 && H5Dread(rho, H5T_NATIVE_FLOAT, msr, fsr, H5P_DEFAULT, r) >= 0;
}

}  // namespace

// ---- writer -----------------------------------------------------------------------------------------

struct WakeTableWriter::Impl {
  Handle file, vel, rho;
};

WakeTableWriter::WakeTableWriter(const std::string& path, const WakeTableInfo& info, bool resume, int keep_frames)
    : impl_(std::make_unique<Impl>()), info_(info), path_(path) {
  const Hdf5Lock hdf5_lock(hdf5_mutex());
  try {
    quiet();
    if (info.shape[0] < 2 || info.shape[1] < 2 || info.shape[2] < 2)
      throw TableError("wake table: the grid needs at least 2 points per axis");
    if (!(info.spacing > 0) || !(info.frame_interval > 0)) throw TableError("wake table: spacing and frame interval must be > 0");
    const hsize_t nx = info.shape[0], ny = info.shape[1], nz = info.shape[2];
    if (resume) {
      impl_->file = Handle(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
      if (impl_->file < 0) throw TableError("wake table '" + path + "': cannot reopen it to resume");
      impl_->vel = Handle(H5Dopen2(impl_->file, "/velocity", H5P_DEFAULT), H5Dclose);
      impl_->rho = Handle(H5Dopen2(impl_->file, "/density", H5P_DEFAULT), H5Dclose);
      if (impl_->vel < 0 || impl_->rho < 0) throw TableError("wake table '" + path + "': datasets missing, cannot resume");
      const hsize_t dv[5] = {static_cast<hsize_t>(keep_frames), nz, ny, nx, 3}, dr[4] = {static_cast<hsize_t>(keep_frames), nz, ny, nx};
      ok(H5Dset_extent(impl_->vel, dv), "resizing /velocity");
      ok(H5Dset_extent(impl_->rho, dr), "resizing /density");
      info_.frames = keep_frames;
    } else {
      std::error_code ec;
      if (std::filesystem::path(path).has_parent_path()) std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
      impl_->file = Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
      if (impl_->file < 0) throw TableError("wake table: cannot create '" + path + "'");
      Handle disk_type = info.half_precision ? half_type() : Handle(H5Tcopy(H5T_IEEE_F32LE), H5Tclose);
      const hsize_t dv[5] = {0, nz, ny, nx, 3}, mv[5] = {H5S_UNLIMITED, nz, ny, nx, 3}, cv[5] = {1, nz, ny, nx, 3};
      const hsize_t dr[4] = {0, nz, ny, nx}, mr[4] = {H5S_UNLIMITED, nz, ny, nx}, cr[4] = {1, nz, ny, nx};
      Handle sv(H5Screate_simple(5, dv, mv), H5Sclose), sr(H5Screate_simple(4, dr, mr), H5Sclose);
      Handle pv(H5Pcreate(H5P_DATASET_CREATE), H5Pclose), pr(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
      ok(H5Pset_chunk(pv, 5, cv), "chunking");  // one chunk per frame
      ok(H5Pset_chunk(pr, 4, cr), "chunking");
      impl_->vel = Handle(H5Dcreate2(impl_->file, "/velocity", disk_type, sv, H5P_DEFAULT, pv, H5P_DEFAULT), H5Dclose);
      impl_->rho = Handle(H5Dcreate2(impl_->file, "/density", disk_type, sr, H5P_DEFAULT, pr, H5P_DEFAULT), H5Dclose);
      if (impl_->vel < 0 || impl_->rho < 0) throw TableError("wake table: cannot create the datasets in '" + path + "'");
      const hid_t f = impl_->file;
      write_attr(f, "format_version", std::vector<double>{static_cast<double>(kWakeTableFormatVersion)});
      write_attr(f, "generator", std::string("ship_lrm wake"));
      write_attr(f, "origin", std::vector<double>(info.origin.begin(), info.origin.end()));
      write_attr(f, "spacing", std::vector<double>{info.spacing});
      write_attr(f, "shape", std::vector<double>{double(nx), double(ny), double(nz)});
      write_attr(f, "frame_interval", std::vector<double>{info.frame_interval});
      write_attr(f, "start_time", std::vector<double>{info.start_time});
      write_attr(f, "free_stream", std::vector<double>(info.free_stream.begin(), info.free_stream.end()));
      write_attr(f, "free_density", std::vector<double>{info.free_density});
      write_attr(f, "ship", info.ship);
      write_attr(f, "scale", info.scale);
      write_attr(f, "motion", info.motion);
      write_attr(f, "units", std::string(kWakeTableUnits));
      write_attr(f, "frame", std::string("mean ship frame: x forward, y starboard, z down; origin at the hangar-door base"));
      write_attr(f, "frames", std::vector<double>{0.0});
      info_.frames = 0;
    }
    write_attr(impl_->file, "frames", std::vector<double>{static_cast<double>(info_.frames)});
    H5Fflush(impl_->file, H5F_SCOPE_GLOBAL);
  } catch (...) {
    impl_.reset();  // its handles close under the lock
    throw;
  }
}

WakeTableWriter::~WakeTableWriter() {
  const Hdf5Lock hdf5_lock(hdf5_mutex());
  try {
    close();
  } catch (...) {
  }
}

void WakeTableWriter::append(const std::vector<float>& velocity, const std::vector<float>& density) {
  const Hdf5Lock hdf5_lock(hdf5_mutex());
  if (!impl_ || impl_->file < 0) throw TableError("wake table: append after close");
  const std::size_t n = info_.points();
  if (velocity.size() != 3 * n || density.size() != n) throw TableError("wake table: a frame has the wrong number of values");
  const hsize_t nx = info_.shape[0], ny = info_.shape[1], nz = info_.shape[2], f = static_cast<hsize_t>(info_.frames);
  const hsize_t dv[5] = {f + 1, nz, ny, nx, 3}, dr[4] = {f + 1, nz, ny, nx};
  ok(H5Dset_extent(impl_->vel, dv), "extending /velocity");
  ok(H5Dset_extent(impl_->rho, dr), "extending /density");
  if (!frame_box(impl_->vel, impl_->rho, true, f, {0, 0, 0}, info_.shape, const_cast<float*>(velocity.data()),
                 const_cast<float*>(density.data())))
    throw TableError("wake table: writing frame " + std::to_string(f) + " failed (disk full?)");
  ++info_.frames;
  write_attr(impl_->file, "frames", std::vector<double>{static_cast<double>(info_.frames)});
  H5Fflush(impl_->file, H5F_SCOPE_GLOBAL);
}

void WakeTableWriter::write_statistic(const std::string& name, const std::vector<float>& values, const std::vector<int>& dims) {
  const Hdf5Lock hdf5_lock(hdf5_mutex());
  std::size_t n = 1;
  std::vector<hsize_t> d;
  for (int x : dims) {
    n *= static_cast<std::size_t>(x);
    d.push_back(static_cast<hsize_t>(x));
  }
  if (n != values.size()) throw TableError("wake table: statistic '" + name + "' has the wrong size");
  if (H5Lexists(impl_->file, "/statistics", H5P_DEFAULT) <= 0) {
    Handle g(H5Gcreate2(impl_->file, "/statistics", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  }
  const std::string full = "/statistics/" + name;
  if (H5Lexists(impl_->file, full.c_str(), H5P_DEFAULT) > 0) H5Ldelete(impl_->file, full.c_str(), H5P_DEFAULT);
  Handle space(H5Screate_simple(static_cast<int>(d.size()), d.data(), nullptr), H5Sclose);
  Handle ds(H5Dcreate2(impl_->file, full.c_str(), H5T_IEEE_F32LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  ok(H5Dwrite(ds, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "writing statistic " + name);
  H5Fflush(impl_->file, H5F_SCOPE_GLOBAL);
}

void WakeTableWriter::close() {
  const Hdf5Lock hdf5_lock(hdf5_mutex());
  if (!impl_ || impl_->file < 0) return;
  write_xdmf();  // once, not after every frame (it lists them all)
  impl_->vel.reset();
  impl_->rho.reset();
  impl_->file.reset();
}

void WakeTableWriter::write_xdmf() const {
  const std::filesystem::path p(path_);
  const std::string file = p.filename().string();
  std::filesystem::path side = p;
  side.replace_extension(".xdmf");
  const std::string tmp = side.string() + ".tmp";
  std::ofstream x(tmp);
  const int nx = info_.shape[0], ny = info_.shape[1], nz = info_.shape[2], F = info_.frames;
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n <Domain>\n  <Grid Name=\"wake\" GridType=\"Collection\" "
       "CollectionType=\"Temporal\">\n";
  for (int f = 0; f < F; ++f) {
    x << "   <Grid Name=\"frame" << f << "\" GridType=\"Uniform\">\n";
    x << "    <Time Value=\"" << info_.start_time + f * info_.frame_interval << "\"/>\n";
    x << "    <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" << nz << " " << ny << " " << nx << "\"/>\n";
    x << "    <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n";
    x << "     <DataItem Dimensions=\"3\" Format=\"XML\">" << info_.origin[2] << " " << info_.origin[1] << " " << info_.origin[0]
      << "</DataItem>\n";
    x << "     <DataItem Dimensions=\"3\" Format=\"XML\">" << info_.spacing << " " << info_.spacing << " " << info_.spacing
      << "</DataItem>\n";
    x << "    </Geometry>\n";
    // one attribute: frame f of a dataset [frames][nz][ny][nx](components), read through HDF5's conversion
    // into float32 whether stored as float16 or float32
    const auto attribute = [&](const char* name, const char* type, const char* dataset, bool vector) {
      const std::string dims = std::to_string(nz) + " " + std::to_string(ny) + " " + std::to_string(nx) + (vector ? " 3" : "");
      x << "    <Attribute Name=\"" << name << "\" AttributeType=\"" << type << "\" Center=\"Node\">\n";
      x << "     <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << dims << "\">\n";
      x << "      <DataItem Dimensions=\"3 " << (vector ? 5 : 4) << "\" Format=\"XML\">" << f
        << (vector ? " 0 0 0 0 1 1 1 1 1 1 " : " 0 0 0 1 1 1 1 1 ") << dims << "</DataItem>\n";
      x << "      <DataItem Dimensions=\"" << F << " " << dims << "\" NumberType=\"Float\" Precision=\"4\" Format=\"HDF\">" << file << ":"
        << dataset << "</DataItem>\n";
      x << "     </DataItem>\n    </Attribute>\n";
    };
    attribute("velocity", "Vector", "/velocity", true);
    attribute("density", "Scalar", "/density", false);
    x << "   </Grid>\n";
  }
  x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  x.close();
  std::error_code ec;
  std::filesystem::rename(tmp, side, ec);
}

// ---- reader -----------------------------------------------------------------------------------------

struct WakeTable::Impl {
  Handle file, vel, rho;
  std::string path;
};

struct WakeTable::ReadAhead {
  std::future<bool> done;
  Window w;
  int frame = -1;
};

WakeTable::WakeTable(const std::string& path, std::size_t window_points) : impl_(std::make_unique<Impl>()), max_points_(window_points) {
  const Hdf5Lock hdf5_lock(hdf5_mutex());
  try {
    quiet();
    impl_->path = path;
    if (!std::filesystem::exists(path))
      throw TableError("wake table '" + path + "' does not exist; make one with `ship_lrm wake --preset default --out " + path + "`");
    if (H5Fis_hdf5(path.c_str()) <= 0) throw TableError("wake table '" + path + "' is not an HDF5 file (or is truncated)");
    impl_->file = Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (impl_->file < 0) throw TableError("wake table '" + path + "' cannot be opened (corrupt or truncated HDF5)");
    const hid_t f = impl_->file;
    const int version = static_cast<int>(read_attr_numbers(f, "format_version", 1, path)[0]);
    if (version != kWakeTableFormatVersion)
      throw TableError("wake table '" + path + "' has format version " + std::to_string(version) + "; this program reads version " +
                       std::to_string(kWakeTableFormatVersion) + " (make it again with `ship_lrm wake`)");
    const std::string units = read_attr_string(f, "units", path);
    if (units != kWakeTableUnits)
      throw TableError("wake table '" + path + "' has units '" + units + "', expected '" + kWakeTableUnits + "'");
    const auto o = read_attr_numbers(f, "origin", 3, path);
    info_.origin = {o[0], o[1], o[2]};
    info_.spacing = read_attr_numbers(f, "spacing", 1, path)[0];
    const auto sh = read_attr_numbers(f, "shape", 3, path);
    info_.shape = {static_cast<int>(sh[0]), static_cast<int>(sh[1]), static_cast<int>(sh[2])};
    info_.frame_interval = read_attr_numbers(f, "frame_interval", 1, path)[0];
    info_.start_time = read_attr_numbers(f, "start_time", 1, path)[0];
    const auto fs = read_attr_numbers(f, "free_stream", 3, path);
    info_.free_stream = {fs[0], fs[1], fs[2]};
    info_.free_density = read_attr_numbers(f, "free_density", 1, path)[0];
    info_.ship = read_attr_string(f, "ship", path);
    info_.scale = read_attr_string(f, "scale", path);
    info_.motion = read_attr_string(f, "motion", path);
    if (!(info_.spacing > 0) || !(info_.frame_interval > 0) || info_.shape[0] < 2 || info_.shape[1] < 2 || info_.shape[2] < 2)
      throw TableError("wake table '" + path + "': invalid grid or frame interval attributes");
    impl_->vel = Handle(H5Dopen2(f, "/velocity", H5P_DEFAULT), H5Dclose);
    impl_->rho = Handle(H5Dopen2(f, "/density", H5P_DEFAULT), H5Dclose);
    if (impl_->vel < 0 || impl_->rho < 0) throw TableError("wake table '" + path + "': /velocity or /density is missing");
    Handle sv(H5Dget_space(impl_->vel), H5Sclose), sr(H5Dget_space(impl_->rho), H5Sclose);
    hsize_t dv[5] = {}, dr[4] = {};
    if (H5Sget_simple_extent_ndims(sv) != 5 || H5Sget_simple_extent_ndims(sr) != 4)
      throw TableError("wake table '" + path + "': /velocity or /density has the wrong rank");
    H5Sget_simple_extent_dims(sv, dv, nullptr);
    H5Sget_simple_extent_dims(sr, dr, nullptr);
    const hsize_t nx = info_.shape[0], ny = info_.shape[1], nz = info_.shape[2];
    if (dv[1] != nz || dv[2] != ny || dv[3] != nx || dv[4] != 3 || dr[1] != nz || dr[2] != ny || dr[3] != nx || dv[0] != dr[0])
      throw TableError("wake table '" + path + "': dataset sizes do not match the shape attribute");
    const int written = static_cast<int>(read_attr_numbers(f, "frames", 1, path)[0]);
    info_.frames = static_cast<int>(std::min<hsize_t>(dv[0], static_cast<hsize_t>(std::max(written, 0))));
    if (info_.frames < 1) throw TableError("wake table '" + path + "' holds no frames");
    Handle type(H5Dget_type(impl_->vel), H5Tclose);
    info_.half_precision = H5Tget_size(type) == 2;
  } catch (...) {
    impl_.reset();  // its handles close under the lock
    throw;
  }
}

WakeTable::~WakeTable() {
  if (ahead_ && ahead_->done.valid()) ahead_->done.wait();  // the read-ahead thread uses impl_
  const Hdf5Lock hdf5_lock(hdf5_mutex());
  impl_.reset();
}

void WakeTable::read_frame(int frame, std::vector<float>& velocity, std::vector<float>& density) const {
  const Hdf5Lock hdf5_lock(hdf5_mutex());
  if (frame < 0 || frame >= info_.frames) throw TableError("wake table: frame " + std::to_string(frame) + " out of range");
  const hsize_t f = static_cast<hsize_t>(frame);
  velocity.resize(3 * info_.points());
  density.resize(info_.points());
  if (!frame_box(impl_->vel, impl_->rho, false, f, {0, 0, 0}, info_.shape, velocity.data(), density.data()))
    throw TableError("wake table '" + impl_->path + "': frame " + std::to_string(frame) + " is unreadable (corrupt or truncated file)");
}

namespace {
bool covers_box(const std::array<int, 3>& wlo, const std::array<int, 3>& wn, const std::array<int, 3>& lo, const std::array<int, 3>& hi) {
  for (int d = 0; d < 3; ++d)
    if (wlo[d] > lo[d] || wlo[d] + wn[d] <= hi[d]) return false;
  return true;
}
std::uint64_t next_window_serial() {
  static std::atomic<std::uint64_t> serials{0};
  return ++serials;
}
}  // namespace

bool WakeTable::load(Window& w, int frame, const std::array<int, 3>& a, const std::array<int, 3>& n) const {
  const std::size_t pts = static_cast<std::size_t>(n[0]) * n[1] * n[2];
  w.u.resize(3 * pts);
  w.rho.resize(pts);
  const Hdf5Lock hdf5_lock(hdf5_mutex());
  return frame_box(impl_->vel, impl_->rho, false, static_cast<hsize_t>(frame), a, n, w.u.data(), w.rho.data());
}

void WakeTable::read_ahead(int frame, const Window& like) {
  if (frame >= info_.frames || like.frame < 0) return;
  if (ahead_ && ahead_->frame == frame) return;  // on its way or waiting
  if (w_[frame % 2].frame == frame && w_[frame % 2].lo == like.lo && w_[frame % 2].n == like.n) return;
  if (!ahead_) ahead_ = std::make_unique<ReadAhead>();
  if (ahead_->done.valid()) ahead_->done.wait();  // an older read-ahead that was not used
  ahead_->frame = frame;
  ahead_->w.frame = frame;
  ahead_->w.lo = like.lo;
  ahead_->w.n = like.n;
  ReadAhead* r = ahead_.get();
  r->done = std::async(std::launch::async, [this, r] { return load(r->w, r->frame, r->w.lo, r->w.n); });
}

const WakeTable::Window& WakeTable::window(int frame, const std::array<int, 3>& lo, const std::array<int, 3>& hi) {
  // consecutive frames alternate between the two slots, so the two frames of one sample never evict
  // each other
  Window& w = w_[frame % 2];
  if (w.frame == frame && covers_box(w.lo, w.n, lo, hi)) return w;
  if (ahead_ && ahead_->frame == frame) {  // read ahead: wait for it (usually long done) and take it
    const bool ok = ahead_->done.get();
    ahead_->frame = -1;
    if (ok && covers_box(ahead_->w.lo, ahead_->w.n, lo, hi)) {
      std::swap(w, ahead_->w);
      w.serial = next_window_serial();
      ++loads_;
      ++read_ahead_hits_;
      return w;
    }
  }
  // load a window around [lo, hi] with a margin (the domain moves on), bounded by max_points_
  std::array<int, 3> a{}, n{};
  std::size_t need = 1, with_margin = 1;
  for (int d = 0; d < 3; ++d) {
    need *= static_cast<std::size_t>(hi[d] - lo[d] + 1);
    const int margin = (hi[d] - lo[d] + 1) / 2 + 1;
    a[d] = std::max(0, lo[d] - margin);
    n[d] = std::min(info_.shape[d] - 1, hi[d] + margin) - a[d] + 1;
    with_margin *= static_cast<std::size_t>(n[d]);
  }
  if (need > max_points_)
    throw TableError("wake table: the requested region (" + std::to_string(need) + " grid points) exceeds the window limit of " +
                     std::to_string(max_points_) + " points");
  if (with_margin > max_points_)
    for (int d = 0; d < 3; ++d) {
      a[d] = lo[d];
      n[d] = hi[d] - lo[d] + 1;
    }
  if (!load(w, frame, a, n)) {
    w.frame = -1;
    throw TableError("wake table '" + impl_->path + "': frame " + std::to_string(frame) + " is unreadable (corrupt or truncated file)");
  }
  w.frame = frame;
  w.lo = a;
  w.n = n;
  w.serial = next_window_serial();
  ++loads_;
  return w;
}

namespace {
// Time of a sample as the frames around it and the weight of the second (clamped to the table).
void frame_pair(const WakeTableInfo& info, double t, int& f0, int& f1, double& weight1) {
  double ft = (t - info.start_time) / info.frame_interval;
  ft = std::clamp(ft, 0.0, static_cast<double>(info.frames - 1));
  f0 = std::min(static_cast<int>(ft), info.frames - 1);
  f1 = std::min(f0 + 1, info.frames - 1);
  weight1 = ft - f0;
}
}  // namespace

WakeTable::Frames WakeTable::frames(double t, const std::array<double, 3>& lo_m, const std::array<double, 3>& hi_m) {
  if (!std::isfinite(t)) throw TableError("wake table: sample time is not finite");
  Frames r;
  for (int d = 0; d < 3; ++d) {
    if (!std::isfinite(lo_m[d]) || !std::isfinite(hi_m[d]) || lo_m[d] > hi_m[d])
      throw TableError("wake table: the box to feed is not valid");
    r.grid.origin[d] = info_.origin[d];
    r.grid.shape[d] = info_.shape[d];
    r.grid.free_stream[d] = static_cast<float>(info_.free_stream[d]);
  }
  r.grid.spacing = info_.spacing;
  int f0, f1;
  frame_pair(info_, t, f0, f1, r.grid.weight1);
  // the grid cells the box touches, clipped to the table (a box that misses it: empty windows)
  std::array<int, 3> lo{}, hi{};
  for (int d = 0; d < 3; ++d) {
    const double a = (lo_m[d] - info_.origin[d]) / info_.spacing, b = (hi_m[d] - info_.origin[d]) / info_.spacing;
    if (b < 0.0 || a > info_.shape[d] - 1) return r;
    lo[d] = std::clamp(static_cast<int>(std::floor(a)), 0, info_.shape[d] - 2);
    hi[d] = std::clamp(static_cast<int>(std::floor(b)) + 1, 1, info_.shape[d] - 1);
  }
  const int fr[2] = {f0, f1};
  for (int s = 0; s < 2; ++s) {
    const Window& w = window(fr[s], lo, hi);
    for (int d = 0; d < 3; ++d) {
      r.window[s].lo[d] = w.lo[d];
      r.window[s].n[d] = w.n[d];
    }
    r.window[s].u = w.u.data();
    r.serial[s] = w.serial;
  }
  read_ahead(f1 + 1, w_[f1 % 2]);
  return r;
}

void WakeTable::sample(double t, const std::vector<double>& xyz, std::vector<WakeSample>& out) {
  const std::size_t np = xyz.size() / 3;
  out.resize(np);
  if (!std::isfinite(t)) throw TableError("wake table: sample time is not finite");
  // grid coordinates and the box of the points inside the table
  std::array<int, 3> lo{info_.shape[0], info_.shape[1], info_.shape[2]}, hi{-1, -1, -1};
  std::vector<double> g(xyz.size());
  std::vector<char> in(np);
  const long npl = static_cast<long>(np);
  // Every point is independent: the loops over points run on the OpenMP threads (the LRM's faces
  // have 10^4 - 10^5 points, sampled whenever they are due).
#pragma omp parallel for schedule(static)
  for (long p = 0; p < npl; ++p) {
    for (int d = 0; d < 3; ++d) g[3 * p + d] = (xyz[3 * p + d] - info_.origin[d]) / info_.spacing;
    in[p] = lbm::grid_inside(&g[3 * p], info_.shape.data());
  }
  for (std::size_t p = 0; p < np; ++p) {
    if (!in[p]) continue;
    int i[3];
    double fr[3];
    lbm::grid_cell(&g[3 * p], info_.shape.data(), i, fr);
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], i[d]);
      hi[d] = std::max(hi[d], i[d] + 1);
    }
  }
  const WakeSample free{
      {static_cast<float>(info_.free_stream[0]), static_cast<float>(info_.free_stream[1]), static_cast<float>(info_.free_stream[2])},
      static_cast<float>(info_.free_density)};
  if (hi[0] < 0) {
    std::fill(out.begin(), out.end(), free);
    return;
  }
  int f0, f1;
  double at;
  frame_pair(info_, t, f0, f1, at);
  const Window* w[2] = {&window(f0, lo, hi), &window(f1, lo, hi)};
#pragma omp parallel for schedule(static)
  for (long p = 0; p < npl; ++p) {
    if (!in[p]) {
      out[p] = free;
      continue;
    }
    double acc[4] = {0, 0, 0, 0};
    int i[3];
    double fr[3];
    lbm::grid_cell(&g[3 * p], info_.shape.data(), i, fr);
    for (int s = 0; s < 2; ++s) {  // the same interpolation as the LRM's face feed (grid_feed.hpp)
      const Window& W = *w[s];
      const double wt = s == 0 ? 1.0 - at : at;
      if (wt == 0.0) continue;
      lbm::accumulate_trilinear(W.u.data(), 3, W.lo.data(), W.n.data(), i, fr, wt, acc);
      lbm::accumulate_trilinear(W.rho.data(), 1, W.lo.data(), W.n.data(), i, fr, wt, acc + 3);
    }
    out[p] = {{static_cast<float>(acc[0]), static_cast<float>(acc[1]), static_cast<float>(acc[2])}, static_cast<float>(acc[3])};
  }
  read_ahead(f1 + 1, *w[1]);
}

}  // namespace ship_lrm::wake
