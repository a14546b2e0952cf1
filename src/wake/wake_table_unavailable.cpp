// Stand-in for the HDF5 wake table when the core is built without HDF5 (a bare GPU machine).
#include "ship_lrm/wake/wake_table.hpp"

namespace ship_lrm::wake {
namespace {
[[noreturn]] void unavailable() {
  throw TableError("this build has no HDF5: the wake table is unavailable (install libhdf5-dev and rebuild)");
}
}  // namespace

struct WakeTableWriter::Impl {};
WakeTableWriter::WakeTableWriter(const std::string&, const WakeTableInfo&, bool, int) { unavailable(); }
WakeTableWriter::~WakeTableWriter() = default;
void WakeTableWriter::append(const std::vector<float>&, const std::vector<float>&) { unavailable(); }
void WakeTableWriter::write_statistic(const std::string&, const std::vector<float>&, const std::vector<int>&) { unavailable(); }
void WakeTableWriter::close() {}
void WakeTableWriter::write_xdmf() const {}

struct WakeTable::Impl {};
struct WakeTable::ReadAhead {};
WakeTable::WakeTable(const std::string&, std::size_t) { unavailable(); }
WakeTable::~WakeTable() = default;
void WakeTable::sample(double, const std::vector<double>&, std::vector<WakeSample>&) { unavailable(); }
WakeTable::Frames WakeTable::frames(double, const std::array<double, 3>&, const std::array<double, 3>&) { unavailable(); }
void WakeTable::read_frame(int, std::vector<float>&, std::vector<float>&) const { unavailable(); }
const WakeTable::Window& WakeTable::window(int, const std::array<int, 3>&, const std::array<int, 3>&) { unavailable(); }

}  // namespace ship_lrm::wake
