// The ship-wake table in HDF5 (see wake_table.hpp), through the HDF5 C library.
#include <hdf5.h>

#include <Eigen/Core>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <future>
#include <mutex>

#include "ship_lrm/wake/nested_table.hpp"
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

// Reads a dataset's selection as float32. Through HDF5's conversion, except IEEE binary16 on disk
// (half: raw into `raw`, widened here): HDF5's soft float16 conversion took 2.7 % of a bench-wake
// run's CPU (a window every table frame, read ahead on a thread that takes the LBM threads' cores).
bool read_floats(hid_t set, hid_t mem_space, hid_t file_space, bool half, std::vector<std::uint16_t>& raw, float* out) {
  if (!half) return H5Dread(set, H5T_NATIVE_FLOAT, mem_space, file_space, H5P_DEFAULT, out) >= 0;
  const hssize_t n = H5Sget_select_npoints(mem_space);
  if (n < 0) return false;
  raw.resize(static_cast<std::size_t>(n));
  const Handle type = half_type();
  if (H5Dread(set, type, mem_space, file_space, H5P_DEFAULT, raw.data()) < 0) return false;
  for (std::size_t k = 0; k < raw.size(); ++k) out[k] = Eigen::half_impl::half_to_float(Eigen::half_impl::raw_uint16_to_half(raw[k]));
  return true;
}

// Reads or writes the box [lo, lo + n) (x, y, z) of one frame of /velocity and /density (reading:
// half_vel, half_rho say which is stored as IEEE binary16; raw is the buffer for it).
bool frame_box(hid_t vel, hid_t rho, bool write, hsize_t frame, const std::array<int, 3>& lo, const std::array<int, 3>& n, float* u,
               float* r, bool half_vel = false, bool half_rho = false, std::vector<std::uint16_t>* raw = nullptr) {
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
  std::vector<std::uint16_t> local;
  std::vector<std::uint16_t>& buffer = raw ? *raw : local;
  return read_floats(vel, msv, fsv, half_vel, buffer, u) && read_floats(rho, msr, fsr, half_rho, buffer, r);
}

// Is dataset `set` stored as IEEE binary16 (the layout half_type() writes)?
bool stored_as_half(hid_t set) {
  const Handle type(H5Dget_type(set), H5Tclose);
  const Handle half = half_type();
  return type >= 0 && H5Tequal(type, half) > 0;
}

}  // namespace

// ---- writer -----------------------------------------------------------------------------------------

struct WakeTableWriter::Impl {
  Handle file, vel, rho;
  Handle fine_group, fine_vel, fine_rho;  // a nested table's fine level
};

namespace {
// Chunks of one frame and kChunkEdge^3 nodes (x, y, z; fewer where a level is smaller), byte-shuffled
// and deflated at level 1 where the HDF5 library has deflate (Debian's does). Chosen by measurement,
// docs/benchmarks.md "The wake table on disk": on the default table shuffle + deflate 1 halves the
// size at the cost of a few per cent of the precompute; blocks rather than one chunk per frame, since
// a compressed chunk is inflated whole for every window the reader takes from it.
constexpr hsize_t kChunkEdge = 32;
constexpr unsigned kDeflateLevel = 1;

// Creates /velocity and /density of a level (`where`: "" or "/fine") of shape nx, ny, nz with no
// frames yet.
void create_level(hid_t file, const std::string& where, hid_t disk_type, const std::array<int, 3>& shape, Handle& vel, Handle& rho,
                  const std::string& path) {
  const hsize_t nx = shape[0], ny = shape[1], nz = shape[2];
  const hsize_t bx = std::min(nx, kChunkEdge), by = std::min(ny, kChunkEdge), bz = std::min(nz, kChunkEdge);
  const hsize_t dv[5] = {0, nz, ny, nx, 3}, mv[5] = {H5S_UNLIMITED, nz, ny, nx, 3}, cv[5] = {1, bz, by, bx, 3};
  const hsize_t dr[4] = {0, nz, ny, nx}, mr[4] = {H5S_UNLIMITED, nz, ny, nx}, cr[4] = {1, bz, by, bx};
  Handle sv(H5Screate_simple(5, dv, mv), H5Sclose), sr(H5Screate_simple(4, dr, mr), H5Sclose);
  Handle pv(H5Pcreate(H5P_DATASET_CREATE), H5Pclose), pr(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  ok(H5Pset_chunk(pv, 5, cv), "chunking");
  ok(H5Pset_chunk(pr, 4, cr), "chunking");
  if (H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0 && H5Zfilter_avail(H5Z_FILTER_SHUFFLE) > 0)
    for (hid_t p : {hid_t(pv), hid_t(pr)}) {
      ok(H5Pset_shuffle(p), "the shuffle filter");
      ok(H5Pset_deflate(p, kDeflateLevel), "the deflate filter");
    }
  vel = Handle(H5Dcreate2(file, (where + "/velocity").c_str(), disk_type, sv, H5P_DEFAULT, pv, H5P_DEFAULT), H5Dclose);
  rho = Handle(H5Dcreate2(file, (where + "/density").c_str(), disk_type, sr, H5P_DEFAULT, pr, H5P_DEFAULT), H5Dclose);
  if (vel < 0 || rho < 0) throw TableError("wake table: cannot create the datasets in '" + path + "'");
}

void resize_level(hid_t vel, hid_t rho, const std::array<int, 3>& shape, hsize_t frames, const char* what) {
  const hsize_t nx = shape[0], ny = shape[1], nz = shape[2];
  const hsize_t dv[5] = {frames, nz, ny, nx, 3}, dr[4] = {frames, nz, ny, nx};
  ok(H5Dset_extent(vel, dv), std::string("resizing ") + what + "velocity");
  ok(H5Dset_extent(rho, dr), std::string("resizing ") + what + "density");
}

std::vector<double> numbers(const std::array<int, 3>& a) { return {double(a[0]), double(a[1]), double(a[2])}; }
}  // namespace

WakeTableWriter::WakeTableWriter(const std::string& path, const WakeTableInfo& info, bool resume, int keep_frames)
    : impl_(std::make_unique<Impl>()), info_(info), path_(path) {
  const Hdf5Lock hdf5_lock(hdf5_mutex());
  try {
    quiet();
    if (info.shape[0] < 2 || info.shape[1] < 2 || info.shape[2] < 2)
      throw TableError("wake table: the grid needs at least 2 points per axis");
    if (!(info.spacing > 0) || !(info.frame_interval > 0)) throw TableError("wake table: spacing and frame interval must be > 0");
    check_levels(info, "wake table '" + path + "'");  // before the file is touched
    if (resume) {
      impl_->file = Handle(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
      if (impl_->file < 0) throw TableError("wake table '" + path + "': cannot reopen it to resume");
      impl_->vel = Handle(H5Dopen2(impl_->file, "/velocity", H5P_DEFAULT), H5Dclose);
      impl_->rho = Handle(H5Dopen2(impl_->file, "/density", H5P_DEFAULT), H5Dclose);
      if (impl_->vel < 0 || impl_->rho < 0) throw TableError("wake table '" + path + "': datasets missing, cannot resume");
      resize_level(impl_->vel, impl_->rho, info.shape, static_cast<hsize_t>(keep_frames), "/");
      if (info.fine.ratio > 0) {
        impl_->fine_vel = Handle(H5Dopen2(impl_->file, "/fine/velocity", H5P_DEFAULT), H5Dclose);
        impl_->fine_rho = Handle(H5Dopen2(impl_->file, "/fine/density", H5P_DEFAULT), H5Dclose);
        if (impl_->fine_vel < 0 || impl_->fine_rho < 0)
          throw TableError("wake table '" + path + "': its fine level is missing, cannot resume");
        resize_level(impl_->fine_vel, impl_->fine_rho, info.fine.shape, static_cast<hsize_t>(keep_frames), "/fine/");
      }
      info_.frames = keep_frames;
    } else {
      std::error_code ec;
      if (std::filesystem::path(path).has_parent_path()) std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
      impl_->file = Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
      if (impl_->file < 0) throw TableError("wake table: cannot create '" + path + "'");
      Handle disk_type = info.half_precision ? half_type() : Handle(H5Tcopy(H5T_IEEE_F32LE), H5Tclose);
      create_level(impl_->file, "", disk_type, info.shape, impl_->vel, impl_->rho, path);
      const hid_t f = impl_->file;
      const bool nested = info.fine.ratio > 0;
      if (nested) {
        const WakeTableLevel& l = info.fine;
        impl_->fine_group = Handle(H5Gcreate2(f, "/fine", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
        if (impl_->fine_group < 0) throw TableError("wake table: cannot create /fine in '" + path + "'");
        create_level(f, "/fine", disk_type, l.shape, impl_->fine_vel, impl_->fine_rho, path);
        const hid_t g = impl_->fine_group;
        write_attr(g, "ratio", std::vector<double>{double(l.ratio)});
        write_attr(g, "lo", numbers(l.lo));
        write_attr(g, "shape", numbers(l.shape));
        std::vector<double> origin(3);
        for (int d = 0; d < 3; ++d) origin[d] = info.origin[d] + l.lo[d] * info.spacing;
        write_attr(g, "origin", origin);
        write_attr(g, "spacing", std::vector<double>{info.spacing / l.ratio});
        write_attr(g, "start_time", std::vector<double>{info.start_time});
        write_attr(g, "frame_interval", std::vector<double>{info.frame_interval});
        write_attr(g, "seam", std::vector<double>(l.seam.begin(), l.seam.end()));
        write_attr(g, "seam_cells", std::vector<double>{l.seam_cells});
      }
      write_attr(f, "format_version",
                 std::vector<double>{static_cast<double>(nested ? kWakeTableFormatVersion : kWakeTableSingleLevelVersion)});
      write_attr(f, "generator", std::string("ship_lrm wake"));
      write_attr(f, "origin", std::vector<double>(info.origin.begin(), info.origin.end()));
      write_attr(f, "spacing", std::vector<double>{info.spacing});
      write_attr(f, "shape", numbers(info.shape));
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

void WakeTableWriter::append(const std::vector<float>& velocity, const std::vector<float>& density, const std::vector<float>& fine_velocity,
                             const std::vector<float>& fine_density) {
  const Hdf5Lock hdf5_lock(hdf5_mutex());
  if (!impl_ || impl_->file < 0) throw TableError("wake table: append after close");
  const std::size_t n = info_.points(), nf = info_.fine.ratio > 0 ? info_.fine.points() : 0;
  if (velocity.size() != 3 * n || density.size() != n) throw TableError("wake table: a frame has the wrong number of values");
  if (fine_velocity.size() != 3 * nf || fine_density.size() != nf)
    throw TableError("wake table: a frame's fine level has the wrong number of values");
  const hsize_t f = static_cast<hsize_t>(info_.frames);
  // the fine level first: the frame count (the attribute, written last) never covers a frame a level lacks
  if (nf > 0) {
    resize_level(impl_->fine_vel, impl_->fine_rho, info_.fine.shape, f + 1, "/fine/");
    if (!frame_box(impl_->fine_vel, impl_->fine_rho, true, f, {0, 0, 0}, info_.fine.shape, const_cast<float*>(fine_velocity.data()),
                   const_cast<float*>(fine_density.data())))
      throw TableError("wake table: writing frame " + std::to_string(f) + " of the fine level failed (disk full?)");
  }
  resize_level(impl_->vel, impl_->rho, info_.shape, f + 1, "/");
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
  impl_->fine_vel.reset();
  impl_->fine_rho.reset();
  impl_->fine_group.reset();
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
  const int F = info_.frames;
  const bool nested = info_.fine.ratio > 0;
  // one level's uniform grid at frame f: /velocity and /density under `where` ("" or "/fine")
  const auto level = [&](int f, const char* name, const std::string& where, const std::array<double, 3>& origin, double spacing,
                         const std::array<int, 3>& shape, const char* indent) {
    const int nx = shape[0], ny = shape[1], nz = shape[2];
    x << indent << "<Grid Name=\"" << name << "\" GridType=\"Uniform\">\n";
    if (!nested) x << indent << " <Time Value=\"" << info_.start_time + f * info_.frame_interval << "\"/>\n";
    x << indent << " <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" << nz << " " << ny << " " << nx << "\"/>\n";
    x << indent << " <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n";
    x << indent << "  <DataItem Dimensions=\"3\" Format=\"XML\">" << origin[2] << " " << origin[1] << " " << origin[0] << "</DataItem>\n";
    x << indent << "  <DataItem Dimensions=\"3\" Format=\"XML\">" << spacing << " " << spacing << " " << spacing << "</DataItem>\n";
    x << indent << " </Geometry>\n";
    // one attribute: frame f of a dataset [frames][nz][ny][nx](components), read through HDF5's conversion
    // into float32 whether stored as float16 or float32
    const auto attribute = [&](const char* aname, const char* type, const std::string& dataset, bool vector) {
      const std::string dims = std::to_string(nz) + " " + std::to_string(ny) + " " + std::to_string(nx) + (vector ? " 3" : "");
      x << indent << " <Attribute Name=\"" << aname << "\" AttributeType=\"" << type << "\" Center=\"Node\">\n";
      x << indent << "  <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << dims << "\">\n";
      x << indent << "   <DataItem Dimensions=\"3 " << (vector ? 5 : 4) << "\" Format=\"XML\">" << f
        << (vector ? " 0 0 0 0 1 1 1 1 1 1 " : " 0 0 0 1 1 1 1 1 ") << dims << "</DataItem>\n";
      x << indent << "   <DataItem Dimensions=\"" << F << " " << dims << "\" NumberType=\"Float\" Precision=\"4\" Format=\"HDF\">" << file
        << ":" << dataset << "</DataItem>\n";
      x << indent << "  </DataItem>\n" << indent << " </Attribute>\n";
    };
    attribute("velocity", "Vector", where + "/velocity", true);
    attribute("density", "Scalar", where + "/density", false);
    x << indent << "</Grid>\n";
  };
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n <Domain>\n  <Grid Name=\"wake\" GridType=\"Collection\" "
       "CollectionType=\"Temporal\">\n";
  for (int f = 0; f < F; ++f) {
    const std::string name = "frame" + std::to_string(f);
    if (!nested) {
      level(f, name.c_str(), "", info_.origin, info_.spacing, info_.shape, "   ");
      continue;
    }
    // a nested table: each frame a spatial collection of the two levels (ParaView shows both)
    x << "   <Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n";
    x << "    <Time Value=\"" << info_.start_time + f * info_.frame_interval << "\"/>\n";
    level(f, "coarse", "", info_.origin, info_.spacing, info_.shape, "    ");
    std::array<double, 3> fo{};
    for (int d = 0; d < 3; ++d) fo[d] = info_.origin[d] + info_.fine.lo[d] * info_.spacing;
    level(f, "fine", "/fine", fo, info_.spacing / info_.fine.ratio, info_.fine.shape, "    ");
    x << "   </Grid>\n";
  }
  x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  x.close();
  std::error_code ec;
  std::filesystem::rename(tmp, side, ec);
}

// ---- reader -----------------------------------------------------------------------------------------

namespace {
// The levels of a table file: level 0 /velocity and /density, level 1 (a nested table) /fine/...
class Hdf5Source final : public WindowSource, public LevelSource {
 public:
  Handle file, vel[2], rho[2];
  bool half_vel[2] = {false, false}, half_rho[2] = {false, false};
  std::vector<std::uint16_t> raw;  // binary16 values as read (under the HDF5 lock: one reader at a time)
  std::string path;
  ~Hdf5Source() override {
    const Hdf5Lock hdf5_lock(hdf5_mutex());  // the handles close under the lock
    for (int l = 1; l >= 0; --l) {
      rho[l].reset();
      vel[l].reset();
    }
    file.reset();
  }
  bool read(int level, int frame, const std::array<int, 3>& lo, const std::array<int, 3>& n, float* velocity, float* density) override {
    const Hdf5Lock hdf5_lock(hdf5_mutex());
    if (level < 0 || level > 1 || vel[level] < 0) return false;
    return frame_box(vel[level], rho[level], false, static_cast<hsize_t>(frame), lo, n, velocity, density, half_vel[level], half_rho[level],
                     &raw);
  }
  bool read(int frame, const std::array<int, 3>& lo, const std::array<int, 3>& n, float* velocity, float* density) override {
    return read(0, frame, lo, n, velocity, density);
  }
  std::string name() const override { return "wake table '" + path + "'"; }

  // Opens a level's datasets and checks their sizes against `shape`; the frames they hold.
  hsize_t open_level(int level, const std::string& where, const std::array<int, 3>& shape) {
    vel[level] = Handle(H5Dopen2(file, (where + "/velocity").c_str(), H5P_DEFAULT), H5Dclose);
    rho[level] = Handle(H5Dopen2(file, (where + "/density").c_str(), H5P_DEFAULT), H5Dclose);
    if (vel[level] < 0 || rho[level] < 0) throw TableError(name() + ": " + where + "/velocity or " + where + "/density is missing");
    Handle sv(H5Dget_space(vel[level]), H5Sclose), sr(H5Dget_space(rho[level]), H5Sclose);
    hsize_t dv[5] = {}, dr[4] = {};
    if (H5Sget_simple_extent_ndims(sv) != 5 || H5Sget_simple_extent_ndims(sr) != 4)
      throw TableError(name() + ": " + where + "/velocity or " + where + "/density has the wrong rank");
    H5Sget_simple_extent_dims(sv, dv, nullptr);
    H5Sget_simple_extent_dims(sr, dr, nullptr);
    const hsize_t nx = shape[0], ny = shape[1], nz = shape[2];
    if (dv[1] != nz || dv[2] != ny || dv[3] != nx || dv[4] != 3 || dr[1] != nz || dr[2] != ny || dr[3] != nx || dv[0] != dr[0])
      throw TableError(name() + ": " + (where.empty() ? std::string("dataset sizes") : where + " dataset sizes") +
                       " do not match the shape attribute");
    half_vel[level] = stored_as_half(vel[level]);
    half_rho[level] = stored_as_half(rho[level]);
    return dv[0];
  }
};

std::array<int, 3> ints(const std::vector<double>& v, const std::string& what, const std::string& table) {
  std::array<int, 3> a{};
  for (int d = 0; d < 3; ++d) {
    if (!(std::abs(v[d]) < 1e9) || v[d] != std::floor(v[d])) throw TableError(table + ": attribute '" + what + "' is not a whole number");
    a[d] = static_cast<int>(v[d]);
  }
  return a;
}

bool close_to(double a, double b, double scale) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(scale)); }

// The fine level of a nested table, read and checked against the coarse grid.
void read_fine_level(Hdf5Source& src, WakeTableInfo& info, hsize_t coarse_frames) {
  const std::string& path = src.path;
  const std::string table = src.name();
  if (H5Lexists(src.file, "/fine", H5P_DEFAULT) <= 0) throw TableError(table + " has format version 2 but no fine level (/fine)");
  Handle g(H5Gopen2(src.file, "/fine", H5P_DEFAULT), H5Gclose);
  if (g < 0) throw TableError(table + ": /fine cannot be opened");
  WakeTableLevel& l = info.fine;
  const double ratio = read_attr_numbers(g, "ratio", 1, path)[0];
  if (!(ratio >= 1 && ratio <= 16) || ratio != std::floor(ratio)) throw TableError(table + ": its fine level's ratio is not 1 .. 16");
  l.ratio = static_cast<int>(ratio);
  l.lo = ints(read_attr_numbers(g, "lo", 3, path), "/fine lo", table);
  l.shape = ints(read_attr_numbers(g, "shape", 3, path), "/fine shape", table);
  const auto seam = read_attr_numbers(g, "seam", 6, path);
  for (int k = 0; k < 6; ++k) l.seam[k] = seam[k] == 1.0 ? 1 : (seam[k] == 0.0 ? 0 : 2);
  l.seam_cells = read_attr_numbers(g, "seam_cells", 1, path)[0];
  check_levels(info, table);
  // the levels must agree in frame (grid) and time
  const auto origin = read_attr_numbers(g, "origin", 3, path);
  const double spacing = read_attr_numbers(g, "spacing", 1, path)[0];
  for (int d = 0; d < 3; ++d)
    if (!close_to(origin[d], info.origin[d] + l.lo[d] * info.spacing, info.spacing * info.shape[d]))
      throw TableError(table + ": its levels disagree in frame (the fine level's origin is not its coarse grid point)");
  if (!close_to(spacing * l.ratio, info.spacing, info.spacing))
    throw TableError(table + ": its levels disagree in frame (the fine spacing is not the coarse spacing / ratio)");
  if (!close_to(read_attr_numbers(g, "start_time", 1, path)[0], info.start_time, info.frame_interval) ||
      !close_to(read_attr_numbers(g, "frame_interval", 1, path)[0], info.frame_interval, info.frame_interval))
    throw TableError(table + ": its levels disagree in time (start time or frame interval)");
  const hsize_t fine_frames = src.open_level(1, "/fine", l.shape);
  if (fine_frames < std::min<hsize_t>(coarse_frames, static_cast<hsize_t>(info.frames)))
    throw TableError(table + ": its levels disagree in time (the fine level holds " + std::to_string(fine_frames) + " frames, the coarse " +
                     std::to_string(info.frames) + ")");
}
}  // namespace

std::unique_ptr<WindowSource> open_table_file(const std::string& path, WakeTableInfo& info, WakeTableInfo* stored) {
  const Hdf5Lock hdf5_lock(hdf5_mutex());
  auto src = std::make_unique<Hdf5Source>();
  quiet();
  src->path = path;
  if (!std::filesystem::exists(path))
    throw TableError("wake table '" + path + "' does not exist; make one with `ship_lrm wake --preset default --out " + path + "`");
  if (H5Fis_hdf5(path.c_str()) <= 0) throw TableError("wake table '" + path + "' is not an HDF5 file (or is truncated)");
  src->file = Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (src->file < 0) throw TableError("wake table '" + path + "' cannot be opened (corrupt or truncated HDF5)");
  const hid_t f = src->file;
  const int version = static_cast<int>(read_attr_numbers(f, "format_version", 1, path)[0]);
  if (version != kWakeTableFormatVersion && version != kWakeTableSingleLevelVersion)
    throw TableError("wake table '" + path + "' has format version " + std::to_string(version) + "; this program reads versions " +
                     std::to_string(kWakeTableSingleLevelVersion) + " and " + std::to_string(kWakeTableFormatVersion) +
                     " (make it again with `ship_lrm wake`)");
  const std::string units = read_attr_string(f, "units", path);
  if (units != kWakeTableUnits) throw TableError("wake table '" + path + "' has units '" + units + "', expected '" + kWakeTableUnits + "'");
  WakeTableInfo s;
  const auto o = read_attr_numbers(f, "origin", 3, path);
  s.origin = {o[0], o[1], o[2]};
  s.spacing = read_attr_numbers(f, "spacing", 1, path)[0];
  const auto sh = read_attr_numbers(f, "shape", 3, path);
  s.shape = {static_cast<int>(sh[0]), static_cast<int>(sh[1]), static_cast<int>(sh[2])};
  s.frame_interval = read_attr_numbers(f, "frame_interval", 1, path)[0];
  s.start_time = read_attr_numbers(f, "start_time", 1, path)[0];
  const auto fs = read_attr_numbers(f, "free_stream", 3, path);
  s.free_stream = {fs[0], fs[1], fs[2]};
  s.free_density = read_attr_numbers(f, "free_density", 1, path)[0];
  s.ship = read_attr_string(f, "ship", path);
  s.scale = read_attr_string(f, "scale", path);
  s.motion = read_attr_string(f, "motion", path);
  const hsize_t frames = src->open_level(0, "", s.shape);
  const int written = static_cast<int>(read_attr_numbers(f, "frames", 1, path)[0]);
  s.frames = static_cast<int>(std::min<hsize_t>(frames, static_cast<hsize_t>(std::max(written, 0))));
  Handle type(H5Dget_type(src->vel[0]), H5Tclose);
  s.half_precision = H5Tget_size(type) == 2;
  if (version == kWakeTableFormatVersion) read_fine_level(*src, s, frames);
  if (stored) *stored = s;
  info = served_grid(s);
  if (s.fine.ratio == 0) return src;
  return nested_window_source(std::move(src), s);
}

}  // namespace ship_lrm::wake
