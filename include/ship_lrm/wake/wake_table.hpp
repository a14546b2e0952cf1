// The ship-wake table (thesis 6.3): the air wake of a ship on a regular grid, one frame per
// interval, in HDF5 (one chunk per frame; float16 or float32) with an XDMF side-car that ParaView
// opens as a time series. The reader extracts the window around an LRM domain and interpolates
// trilinearly in space and linearly in time; it holds only that window of two frames in memory, and the
// next frame's, read ahead on a background thread. Its windows come from the file or, through a
// WindowSource, from another process (wake_table.cpp: windows and interpolation; wake_table_hdf5.cpp:
// the file).
//
// Layout (format version 1; version 2 adds the fine level of a nested table):
//   /velocity  [frames][nz][ny][nx][3]  m/s, mean frame (ship_motion.hpp), x forward, y starboard, z down
//   /density   [frames][nz][ny][nx]     kg/m^3
//   attributes of / : format_version, generator, origin[3] (m, ship frame of the mean pose, grid point
//     0), spacing (m), shape[3] (nx, ny, nz), frame_interval (s), start_time (s, time of frame 0),
//     free_stream[3] (m/s), free_density (kg/m^3), ship, scale, motion, units ("m, s, m/s, kg/m^3"),
//     frame ("mean ship frame, FRD, origin at the hangar-door base")
//   /fine/velocity, /fine/density  a finer level over a box of the grid (nested tables, version 2): the
//     same frames at `ratio` times the resolution; attributes of /fine: ratio, lo[3] (the coarse grid
//     point of its first point), shape[3], origin[3], spacing, start_time, frame_interval, seam[6]
//     (the faces x-, x+, y-, y+, z-, z+ blended into the coarse grid), seam_cells. The reader serves
//     both levels as one grid at the fine spacing over the coarse box (nested_table.hpp).
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "ship_lrm/lbm/grid_feed.hpp"

namespace ship_lrm::wake {

// A missing, truncated or invalid table file, a wrong format version or units.
class TableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

constexpr int kWakeTableFormatVersion = 2;       // written for a nested table
constexpr int kWakeTableSingleLevelVersion = 1;  // written for a single-level table; both are read
constexpr const char* kWakeTableUnits = "m, s, m/s, kg/m^3";

// The finer level of a nested table: the coarse grid points lo .. lo + (shape - 1) / ratio, each
// coarse cell refined `ratio` times. seam: the faces (x-, x+, y-, y+, z-, z+) where the reader blends
// the fine values into the coarse ones over `seam_cells` coarse cells (a face on the sea or on the
// coarse grid's boundary has nothing to blend with and is left out).
struct WakeTableLevel {
  int ratio = 0;  // 0: no fine level
  std::array<int, 3> lo{0, 0, 0};
  std::array<int, 3> shape{0, 0, 0};
  std::array<int, 6> seam{1, 1, 1, 1, 1, 1};
  double seam_cells = 2;
  std::size_t points() const { return static_cast<std::size_t>(shape[0]) * shape[1] * shape[2]; }
};

struct WakeTableInfo {
  std::array<double, 3> origin{0, 0, 0};  // m, grid point (0, 0, 0)
  double spacing = 1;                     // m
  std::array<int, 3> shape{0, 0, 0};      // nx, ny, nz
  double frame_interval = 0.02;           // s
  double start_time = 0;                  // s, time of frame 0
  std::array<double, 3> free_stream{0, 0, 0};
  double free_density = 1.225;
  std::string ship, scale, motion;
  bool half_precision = true;  // float16 on disk
  int frames = 0;              // written so far (reader: in the file)
  // A nested table's fine level. Written and stored: the grid above is the coarse one. Served
  // (WakeTable::info()): the grid above is the served one at the fine spacing, `fine` as stored.
  WakeTableLevel fine;
  std::size_t points() const { return static_cast<std::size_t>(shape[0]) * shape[1] * shape[2]; }
  double end_time() const { return start_time + (frames - 1) * frame_interval; }
};

// Writes frames one after the other; each append is flushed, so a stopped run leaves a valid table
// of the frames written so far. The side-car is written on close (a resumed run writes it then).
class WakeTableWriter {
 public:
  // Creates `path` (replacing it) or, with resume, opens it and keeps its first `keep_frames` frames.
  WakeTableWriter(const std::string& path, const WakeTableInfo& info, bool resume = false, int keep_frames = 0);
  ~WakeTableWriter();
  WakeTableWriter(const WakeTableWriter&) = delete;
  WakeTableWriter& operator=(const WakeTableWriter&) = delete;
  // velocity: 3 per point (x fastest, then y, then z), density: 1 per point; a nested table's fine
  // level (info.fine) takes its frame at the same time in fine_velocity and fine_density.
  void append(const std::vector<float>& velocity, const std::vector<float>& density, const std::vector<float>& fine_velocity = {},
              const std::vector<float>& fine_density = {});
  // Extra float datasets (statistics), written under /statistics/<name>.
  void write_statistic(const std::string& name, const std::vector<float>& values, const std::vector<int>& dims);
  int frames() const { return info_.frames; }
  const WakeTableInfo& info() const { return info_; }
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  WakeTableInfo info_;
  std::string path_;
  void write_xdmf() const;
};

// Velocity and density at points; outside the table's box the free stream (documented choice: the
// table covers the wake, the air beyond it is undisturbed). Times before the first frame use the
// first, after the last the last (see covers()).
struct WakeSample {
  std::array<float, 3> u;
  float rho;
};

// Where a table's grid values come from: its HDF5 file, or another process that has the file (the
// ROS wake server's `wake/window` service). read() may be called from the table's read-ahead thread.
class WindowSource {
 public:
  virtual ~WindowSource() = default;
  // Frame `frame`'s box [lo, lo + n) of grid points (x, y, z): velocity, 3 per point, and density,
  // x fastest, into arrays of the box's size. False when it cannot be read (the caller names it).
  virtual bool read(int frame, const std::array<int, 3>& lo, const std::array<int, 3>& n, float* velocity, float* density) = 0;
  virtual std::string name() const = 0;  // for messages: the file, or where the windows come from
};

// Opens an HDF5 table file and checks its format (TableError naming what is wrong): its windows on the
// served grid (a nested table's levels composed, nested_table.hpp), the served grid's attributes in
// `info` (WakeTable checks those) and, if asked, the file's levels as stored in `stored`.
std::unique_ptr<WindowSource> open_table_file(const std::string& path, WakeTableInfo& info, WakeTableInfo* stored = nullptr);

class WakeTable {
 public:
  // Opens and validates (TableError naming what is wrong). `window_points` bounds the memory: the
  // cached window of two frames (and the frame read ahead) holds at most this many grid points per frame.
  explicit WakeTable(const std::string& path, std::size_t window_points = 4u << 20);
  // A table whose grid values come from `source` (info as the file's attributes; checked).
  WakeTable(const WakeTableInfo& info, std::unique_ptr<WindowSource> source, std::size_t window_points = 4u << 20);
  ~WakeTable();
  WakeTable(const WakeTable&) = delete;
  WakeTable& operator=(const WakeTable&) = delete;
  // The served grid (a nested table: the fine spacing over the coarse box; info().fine as stored).
  const WakeTableInfo& info() const { return info_; }
  bool covers(double t) const { return t >= info_.start_time && t <= info_.end_time(); }
  // Samples at n points (xyz interleaved, m, mean frame) at time t. All points must lie in a box that
  // fits the window (else TableError); points outside the table get the free stream.
  void sample(double t, const std::vector<double>& xyz, std::vector<WakeSample>& out);
  // The two frames around time t of a window holding the box [lo, hi] (m, mean frame), for callers
  // that interpolate themselves (lbm/grid_feed.hpp: the LRM's faces, on the host or the GPU). The
  // views point into the table's window memory and stay valid until the next sample() or frames()
  // call. serial: a number unique to each loaded window (process-wide), so that a copy of it (on a
  // GPU) is made once. A box that misses the table gives empty windows (everything free stream).
  struct Frames {
    lbm::GridWindowView window[2];
    std::uint64_t serial[2] = {0, 0};
    lbm::GridFeed grid;  // the grid's geometry, the time weight and the free stream filled in
  };
  Frames frames(double t, const std::array<double, 3>& lo, const std::array<double, 3>& hi);
  // One frame's grid values (tests, plots): velocity 3 per point and density.
  void read_frame(int frame, std::vector<float>& velocity, std::vector<float>& density) const;
  // A box [lo, lo + n) of one frame's grid values (the wake server's windows); TableError for a box
  // outside the grid or a frame that cannot be read.
  void read_box(int frame, const std::array<int, 3>& lo, const std::array<int, 3>& n, std::vector<float>& velocity,
                std::vector<float>& density) const;
  std::size_t window_loads() const { return loads_; }                      // hyperslab reads so far (read-ahead included)
  std::size_t window_read_ahead_hits() const { return read_ahead_hits_; }  // of those, read on the background thread in time

 private:
  std::unique_ptr<WindowSource> source_;
  WakeTableInfo info_;
  std::size_t max_points_;
  std::size_t loads_ = 0;
  struct Window {
    int frame = -1;
    std::array<int, 3> lo{0, 0, 0}, n{0, 0, 0};
    std::vector<float> u, rho;
    std::uint64_t serial = 0;
  };
  Window w_[2];
  const Window& window(int frame, const std::array<int, 3>& lo, const std::array<int, 3>& hi);
  // Read-ahead: after each sample()/frames() the frame after the later one is read on a background
  // thread into a third window with the same box, so that the next frame change finds it in memory
  // (HDF5 reads and float16 conversion take milliseconds: more than a GPU step). HDF5 calls are
  // serialised by a process-wide lock (in the file's source).
  struct ReadAhead;
  std::unique_ptr<ReadAhead> ahead_;
  std::size_t read_ahead_hits_ = 0;
  void read_ahead(int frame, const Window& like);
  bool load(Window& w, int frame, const std::array<int, 3>& a, const std::array<int, 3>& n) const;
  void check_info() const;  // TableError naming the source for an unusable grid, no frames, non-finite values
};

}  // namespace ship_lrm::wake
