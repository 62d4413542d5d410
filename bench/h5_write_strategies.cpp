// How a parallel run should write its frames into the one NAME.h5 (docs/performance.md, "Results file: gathered or
// parallel HDF5"): the two strategies timed on frames shaped like Crumple's, on MPI ranks.
//
//   mpirun -np P build/release/bench/h5_write_strategies [--nodes N,N,...] [--frames F] [--dir DIR] [--keep]
//       [--strategies gathered,gathered_fsync,parallel] [--no-times]
//
// Defaults: --nodes 2e5,1e6, --frames 5, --dir $TMPDIR/crumple_h5_write_strategies (/tmp), all three strategies.
//
// The model: the square tube of decks/tube_impact meshed with about N nodes (a ring of `around` nodes, `around`
// rings of shells along the axis, so N = around x (around + 1) nodes and M = around^2 4-node shells), partitioned
// by partition_model (METIS, as `mpirun -np P crumple run` does on every rank). A node is owned by the lowest domain
// of its elements (parallel/domain.cpp), an element by its domain. Each rank keeps whole-model arrays and fills its
// owned rows only (the other rows hold NaN), as a domain does before the output.
//
// A frame, as /frames/NNNN of NAME.h5 (docs/output-format.md; contiguous float64 datasets, default properties):
//   displacement, velocity, acceleration   N x 3
//   shell4/stress                          M x 3
//   shell4/plastic_strain, thickness, von_mises, pressure, energy_density   M
// with the `time` and `cycle` attributes. Its values are a hash of (frame, field, row, column): every frame differs.
//
// Strategy "gathered" (what Crumple does): per field an MPI_Gatherv of the ranks' owned rows to rank 0 (rank 0
// sends nothing, it holds its rows), rank 0 places them, then rank 0 alone writes the frame into a file it opened
// alone with the default (sec2) driver, H5Dwrite of the whole dataset, and H5Fflush, as ResultsFile::write_frame.
// The sec2 flush hands the data to the kernel and does not sync it to the disk.
// Strategy "gathered_fsync": the same, and fsync of the file after the flush: the same durability as the next one.
// Strategy "parallel": every rank has the file open with H5Pset_fapl_mpio; every rank creates the group and the
// datasets (collective), selects its owned rows as a union of hyperslabs (the same selection in its whole-model array
// and in the dataset) and writes them with H5Pset_dxpl_mpio(H5FD_MPIO_COLLECTIVE); then H5Fflush (collective),
// which the MPI-IO driver ends with MPI_File_sync, an fsync of the file (seen with strace).
//
// Timing: MPI_Barrier, MPI_Wtime, the frame, MPI_Barrier, MPI_Wtime, so a frame's time is the slowest rank's. The
// phases are gather (gathered only: until rank 0 holds every row), write (groups, datasets, H5Dwrite) and flush
// (H5Fflush, and the fsync). Before each frame (not timed) rank 0 calls sync(), so that no frame pays for the
// write-back of an earlier one (in a run, the kernel writes a frame back during the cycles before the next). Each
// strategy has its own file (DIR/STRATEGY_P_N.h5), opened before the first frame and
// closed after the last (both timed apart, not in the frames); the strategies' frames alternate. The best of F
// frames is reported, with all of them. The selections and Gatherv counts are made once, not timed (ownership does
// not change during a run).
//
// Check: after the files are closed, rank 0 reads every dataset of every frame back from each file and compares it
// bit for bit (memcmp) with the values it was written from, so files that pass hold the same data.
// --keep leaves the files (for cmp); --no-times writes no object times (H5Pset_obj_track_times), so that files with
// the same content can be compared byte for byte.
#include <fmt/format.h>
#include <hdf5.h>
#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "crumple/parallel/partition.hpp"

namespace {

using namespace crumple;

struct Options {
  std::vector<long long> nodes{200000, 1000000};
  int frames = 5;
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "crumple_h5_write_strategies";
  // gathered, gathered_fsync, parallel
  std::array<bool, 3> strategies{true, true, true};
  bool keep = false, no_times = false;
};

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    parts.push_back(text.substr(at, comma - at));
    at = comma + 1;
  }
  return parts;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string key = argv[i];
    if (key == "--keep") {
      o.keep = true;
      continue;
    }
    if (key == "--no-times") {
      o.no_times = true;
      continue;
    }
    if (i + 1 >= argc) throw std::runtime_error("option " + key + " needs a value");
    const std::string value = argv[++i];
    if (key == "--nodes") {
      o.nodes.clear();
      for (const std::string& s : split(value)) o.nodes.push_back(static_cast<long long>(std::stod(s)));
    } else if (key == "--frames") {
      o.frames = std::stoi(value);
    } else if (key == "--dir") {
      o.dir = value;
    } else if (key == "--strategies") {
      o.strategies = {false, false, false};
      for (const std::string& s : split(value)) {
        if (s == "gathered") o.strategies[0] = true;
        else if (s == "gathered_fsync") o.strategies[1] = true;
        else if (s == "parallel") o.strategies[2] = true;
        else throw std::runtime_error("unknown strategy " + s + " (gathered, gathered_fsync, parallel)");
      }
    } else {
      throw std::runtime_error("unknown option " + key);
    }
  }
  if (o.frames < 1) throw std::runtime_error("--frames must be at least 1");
  return o;
}

// decks/tube_impact's square tube (50 x 50 mm, 200 mm long) with `around` nodes per ring (a multiple of 4) and
// `around` rings of shells; Ishell 24 with 5 points, so METIS sees the weights of the tube's shells.
Model square_tube(int around) {
  const int along = around;
  Model m;
  const double side = 50.0, length = 200.0, size = 4 * side / around;
  for (int j = 0; j <= along; ++j)
    for (int k = 0; k < around; ++k) {
      const int face = k / (around / 4);
      const double s = (k % (around / 4)) * size - side / 2, h = side / 2;
      const double y[4] = {s, h, -s, -h}, z[4] = {-h, s, h, -s};
      m.nodes.user_id.push_back(static_cast<std::int64_t>(m.nodes.size()) + 1);
      m.nodes.x.push_back(length * j / along), m.nodes.y.push_back(y[face]), m.nodes.z.push_back(z[face]);
    }
  ElementTable& shells = m.elements[static_cast<std::size_t>(ElementKind::Shell4)];
  for (int j = 0; j < along; ++j)
    for (int k = 0; k < around; ++k) {
      const int k1 = (k + 1) % around;
      shells.user_id.push_back(static_cast<std::int64_t>(shells.size()) + 1);
      shells.part.push_back(0);
      for (const int node : {j * around + k, (j + 1) * around + k, (j + 1) * around + k1, j * around + k1})
        shells.connectivity.push_back(node);
    }
  m.parts.push_back(Part{});
  m.parts[0].property = 0, m.parts[0].material = 0;
  m.formulations.push_back(ResolvedFormulation{});
  m.formulations[0].ishell = 24, m.formulations[0].n_points = 5;
  return m;
}

struct Run {
  std::size_t start = 0, count = 0;
};

// The runs of consecutive rows with the same owner, per owner.
std::vector<std::vector<Run>> runs_of(const std::vector<std::int32_t>& owner, int ranks) {
  std::vector<std::vector<Run>> runs(static_cast<std::size_t>(ranks));
  for (std::size_t i = 0; i < owner.size();) {
    std::size_t j = i;
    while (j < owner.size() && owner[j] == owner[i]) ++j;
    runs[static_cast<std::size_t>(owner[i])].push_back({i, j - i});
    i = j;
  }
  return runs;
}

std::size_t rows_in(const std::vector<Run>& runs) {
  std::size_t n = 0;
  for (const Run& r : runs) n += r.count;
  return n;
}

// A field of the frame: its dataset path in the frame group, its row kind (nodes or elements) and its width.
struct Field {
  const char* name;
  bool nodal;
  std::size_t width;
};
constexpr std::array<Field, 9> kFields{{{"displacement", true, 3},
                                        {"velocity", true, 3},
                                        {"acceleration", true, 3},
                                        {"shell4/stress", false, 3},
                                        {"shell4/plastic_strain", false, 1},
                                        {"shell4/thickness", false, 1},
                                        {"shell4/von_mises", false, 1},
                                        {"shell4/pressure", false, 1},
                                        {"shell4/energy_density", false, 1}}};

std::uint64_t mix(std::uint64_t z) {  // splitmix64's finaliser
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// The value of a frame's field at (row, column): 53 random bits in [-1, 1).
double value(int frame, std::size_t field, std::size_t row, std::size_t column) {
  const std::uint64_t key = mix(mix(static_cast<std::uint64_t>(frame) * 16 + field) ^ (row * 4 + column));
  return static_cast<double>(key >> 11) * 0x1p-52 - 1.0;
}

void fill_rows(std::vector<double>& data, int frame, std::size_t field, std::size_t width, const std::vector<Run>& runs) {
  for (const Run& r : runs)
    for (std::size_t row = r.start; row < r.start + r.count; ++row)
      for (std::size_t c = 0; c < width; ++c) data[row * width + c] = value(frame, field, row, c);
}

// HDF5 identifiers closed on scope exit.
class Id {
 public:
  Id() = default;
  Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {
    if (id < 0) throw std::runtime_error("HDF5 call failed");
  }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  Id(Id&& o) noexcept : id_(std::exchange(o.id_, -1)), close_(o.close_) {}
  Id& operator=(Id&& o) noexcept {
    reset();
    id_ = std::exchange(o.id_, -1), close_ = o.close_;
    return *this;
  }
  ~Id() { reset(); }
  void reset() {
    if (id_ >= 0 && close_ != nullptr) close_(id_);
    id_ = -1;
  }
  [[nodiscard]] hid_t get() const { return id_; }

 private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

void check(herr_t status, const char* what) {
  if (status < 0) throw std::runtime_error(std::string("HDF5: ") + what);
}

struct Phases {
  double gather = 0.0, write = 0.0, flush = 0.0;
  [[nodiscard]] double total() const { return gather + write + flush; }
};

// One size on this rank: the model's ownership, the whole-model arrays, the layouts of both strategies.
class Bench {
 public:
  Bench(const Options& o, long long target_nodes, int rank, int ranks) : o_(o), rank_(rank), ranks_(ranks) {
    around_ = std::max(4, static_cast<int>(std::lround(std::sqrt(static_cast<double>(target_nodes)) / 4.0)) * 4);
    const Model m = square_tube(around_);
    nodes_ = m.nodes.size();
    elements_ = m.elements[0].size();
    const double start = MPI_Wtime();
    const Partition p = partition_model(m, ranks);
    partition_seconds_ = MPI_Wtime() - start;
    std::vector<std::int32_t> node_owner(nodes_, std::numeric_limits<std::int32_t>::max());
    const std::vector<std::int32_t>& domain = p.domain_of_element[0];
    for (std::size_t e = 0; e < elements_; ++e)
      for (std::size_t a = 0; a < 4; ++a) {
        std::int32_t& owner = node_owner[static_cast<std::size_t>(m.elements[0].connectivity[e * 4 + a])];
        owner = std::min(owner, domain[e]);
      }
    runs_[0] = runs_of(node_owner, ranks);
    runs_[1] = runs_of(domain, ranks);
    for (std::size_t f = 0; f < kFields.size(); ++f)
      data_[f].assign(rows(kFields[f]) * kFields[f].width, std::numeric_limits<double>::quiet_NaN());
  }

  [[nodiscard]] std::size_t nodes() const { return nodes_; }
  [[nodiscard]] std::size_t elements() const { return elements_; }
  [[nodiscard]] int around() const { return around_; }
  [[nodiscard]] double partition_seconds() const { return partition_seconds_; }
  [[nodiscard]] const std::vector<std::vector<Run>>& runs(bool nodal) const { return runs_[nodal ? 0 : 1]; }
  [[nodiscard]] std::size_t rows(const Field& f) const { return f.nodal ? nodes_ : elements_; }
  [[nodiscard]] double frame_bytes() const {
    double bytes = 0.0;
    for (const Field& f : kFields) bytes += static_cast<double>(rows(f) * f.width) * 8.0;
    return bytes;
  }

  // This rank's owned rows of every field at `frame` (not timed: the solver has them).
  void fill(int frame) {
    for (std::size_t f = 0; f < kFields.size(); ++f)
      fill_rows(data_[f], frame, f, kFields[f].width, runs(kFields[f].nodal)[static_cast<std::size_t>(rank_)]);
  }

  Id file_properties(bool mpio) const {
    Id fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    if (mpio) check(H5Pset_fapl_mpio(fapl.get(), MPI_COMM_WORLD, MPI_INFO_NULL), "fapl mpio");
    // As ResultsFile (src/output/results_file.cpp).
    check(H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG), "fclose degree");
    check(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST), "libver bounds");
    return fapl;
  }

  Id create_file(const std::filesystem::path& path, bool mpio) const {
    Id fapl = file_properties(mpio);
    Id fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose), ocpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
    if (o_.no_times) check(H5Pset_obj_track_times(fcpl.get(), 0), "times"), check(H5Pset_obj_track_times(ocpl.get(), 0), "times");
    Id file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get()), H5Fclose);
    Id frames(H5Gcreate2(file.get(), "frames", H5P_DEFAULT, ocpl.get(), H5P_DEFAULT), H5Gclose);
    check(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), "flush");
    return file;
  }

  // Strategy "gathered": the Gatherv layouts, made once.
  void prepare_gathered() {
    for (int k = 0; k < 2; ++k) {
      const auto& runs = runs_[static_cast<std::size_t>(k)];
      auto& counts = rank_rows_[static_cast<std::size_t>(k)];
      counts.assign(static_cast<std::size_t>(ranks_), 0);
      for (int r = 1; r < ranks_; ++r) counts[static_cast<std::size_t>(r)] = rows_in(runs[static_cast<std::size_t>(r)]);
    }
  }

  Phases write_gathered(hid_t file, int frame, bool sync) {
    Phases ph;
    settle();
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    for (std::size_t f = 0; f < kFields.size(); ++f) {
      const Field& field = kFields[f];
      const std::vector<std::vector<Run>>& runs = this->runs(field.nodal);
      const std::vector<std::size_t>& rank_rows = rank_rows_[field.nodal ? 0 : 1];
      std::vector<double>& data = data_[f];
      const std::size_t w = field.width;
      if (rank_ == 0) {
        std::vector<int> counts(static_cast<std::size_t>(ranks_)), displacements(static_cast<std::size_t>(ranks_));
        std::size_t at = 0;
        for (std::size_t r = 0; r < static_cast<std::size_t>(ranks_); ++r) {
          counts[r] = static_cast<int>(rank_rows[r] * w), displacements[r] = static_cast<int>(at);
          at += rank_rows[r] * w;
        }
        receive_.resize(at);
        MPI_Gatherv(nullptr, 0, MPI_DOUBLE, receive_.data(), counts.data(), displacements.data(), MPI_DOUBLE, 0,
                    MPI_COMM_WORLD);
        const double* from = receive_.data();
        for (std::size_t r = 1; r < static_cast<std::size_t>(ranks_); ++r)
          for (const Run& run : runs[r]) {
            std::memcpy(data.data() + run.start * w, from, run.count * w * sizeof(double));
            from += run.count * w;
          }
      } else {
        send_.clear();
        for (const Run& run : runs[static_cast<std::size_t>(rank_)])
          send_.insert(send_.end(), data.begin() + static_cast<std::ptrdiff_t>(run.start * w),
                       data.begin() + static_cast<std::ptrdiff_t>((run.start + run.count) * w));
        MPI_Gatherv(send_.data(), static_cast<int>(send_.size()), MPI_DOUBLE, nullptr, nullptr, nullptr, MPI_DOUBLE, 0,
                    MPI_COMM_WORLD);
      }
    }
    const double t1 = MPI_Wtime();
    double t2 = t1;
    if (rank_ == 0) {
      write_frame_objects(file, frame, [&](hid_t set, std::size_t f) {
        check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data_[f].data()), "write");
      });
      t2 = MPI_Wtime();
      check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush");
      if (sync) {  // what the MPI-IO driver's flush does (MPI_File_sync)
        void* handle = nullptr;
        check(H5Fget_vfd_handle(file, H5P_DEFAULT, &handle), "file handle");
        if (fsync(*static_cast<int*>(handle)) != 0) throw std::runtime_error("fsync failed");
      }
    }
    MPI_Barrier(MPI_COMM_WORLD);
    const double t3 = MPI_Wtime();
    ph.gather = t1 - t0, ph.write = t2 - t1, ph.flush = t3 - t2;
    return ph;
  }

  // Strategy "parallel": this rank's selection in a dataset of each width, made once. The same selection serves as
  // the memory space (the whole-model array has the dataset's shape).
  void prepare_parallel() {
    for (int k = 0; k < 2; ++k) {
      const std::vector<Run>& mine = runs_[static_cast<std::size_t>(k)][static_cast<std::size_t>(rank_)];
      const hsize_t rows = k == 0 ? nodes_ : elements_;
      for (hsize_t w : {hsize_t{1}, hsize_t{3}}) {
        const std::array<hsize_t, 2> dims{rows, w};
        Id space(H5Screate_simple(w == 1 ? 1 : 2, dims.data(), nullptr), H5Sclose);
        check(H5Sselect_none(space.get()), "select none");
        for (const Run& run : mine) {
          const std::array<hsize_t, 2> start{run.start, 0}, count{1, 1}, block{run.count, w};
          check(H5Sselect_hyperslab(space.get(), H5S_SELECT_OR, start.data(), nullptr, count.data(), block.data()),
                "select");
        }
        selections_[static_cast<std::size_t>(k)][w == 1 ? 0 : 1] = std::move(space);
      }
    }
    collective_ = Id(H5Pcreate(H5P_DATASET_XFER), H5Pclose);
    check(H5Pset_dxpl_mpio(collective_.get(), H5FD_MPIO_COLLECTIVE), "dxpl mpio");
  }

  Phases write_parallel(hid_t file, int frame) {
    Phases ph;
    settle();
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    write_frame_objects(file, frame, [&](hid_t set, std::size_t f) {
      const Field& field = kFields[f];
      const hid_t space = selections_[field.nodal ? 0 : 1][field.width == 1 ? 0 : 1].get();
      check(H5Dwrite(set, H5T_NATIVE_DOUBLE, space, space, collective_.get(), data_[f].data()), "write");
    });
    const double t1 = MPI_Wtime();
    check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush");
    MPI_Barrier(MPI_COMM_WORLD);
    const double t2 = MPI_Wtime();
    ph.write = t1 - t0, ph.flush = t2 - t1;
    return ph;
  }

  // Rank 0, after the files are closed: every dataset of every frame of `path` against the values it was written
  // from, bit for bit (so files that pass hold the same data). Returns the first difference, or "".
  std::string compare(const std::filesystem::path& path) const {
    Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    std::vector<double> expected, got;
    for (int frame = 0; frame < o_.frames; ++frame)
      for (std::size_t f = 0; f < kFields.size(); ++f) {
        const Field& field = kFields[f];
        const std::string name = fmt::format("frames/{:04}/{}", frame, field.name);
        expected.assign(rows(field) * field.width, 0.0);
        fill_rows(expected, frame, f, field.width, {Run{0, rows(field)}});
        if (!read(file.get(), name, got)) return path.filename().string() + ": " + name + " unreadable";
        if (got.size() != expected.size() ||
            std::memcmp(got.data(), expected.data(), expected.size() * sizeof(double)) != 0)
          return path.filename().string() + ": " + name + " differs from the values written";
      }
    return "";
  }

 private:
  // Before every frame, not timed: the disk writes of the frames before it finished (sync), as in a run, where the
  // kernel writes a frame back during the seconds of cycles before the next; without it a frame pays for the
  // write-back of the one before, or of the other strategy's file (measured: 30 to 330 ms for the same frame).
  void settle() const {
    if (rank_ == 0) sync();
  }

  template <class WriteField>
  void write_frame_objects(hid_t file, int frame, WriteField&& write_field) const {
    Id ocpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose), dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    if (o_.no_times) check(H5Pset_obj_track_times(ocpl.get(), 0), "times"), check(H5Pset_obj_track_times(dcpl.get(), 0), "times");
    const std::string name = fmt::format("frames/{:04}", frame);
    Id group(H5Gcreate2(file, name.c_str(), H5P_DEFAULT, ocpl.get(), H5P_DEFAULT), H5Gclose);
    scalar_attribute(group.get(), "time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0.01 * frame);
    scalar_attribute(group.get(), "cycle", H5T_STD_I64LE, H5T_NATIVE_INT64, static_cast<std::int64_t>(1000 * frame));
    Id shells(H5Gcreate2(group.get(), "shell4", H5P_DEFAULT, ocpl.get(), H5P_DEFAULT), H5Gclose);
    for (std::size_t f = 0; f < kFields.size(); ++f) {
      const Field& field = kFields[f];
      const std::array<hsize_t, 2> dims{rows(field), field.width};
      Id space(H5Screate_simple(field.width == 1 ? 1 : 2, dims.data(), nullptr), H5Sclose);
      Id set(H5Dcreate2(group.get(), field.name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
             H5Dclose);
      write_field(set.get(), f);
    }
  }

  template <class T>
  static void scalar_attribute(hid_t at, const char* name, hid_t file_type, hid_t memory_type, T v) {
    Id space(H5Screate(H5S_SCALAR), H5Sclose);
    Id attr(H5Acreate2(at, name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    check(H5Awrite(attr.get(), memory_type, &v), "attribute");
  }

  static bool read(hid_t file, const std::string& name, std::vector<double>& out) {
    if (H5Lexists(file, name.c_str(), H5P_DEFAULT) <= 0) return false;
    Id set(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose);
    Id space(H5Dget_space(set.get()), H5Sclose);
    const hssize_t n = H5Sget_simple_extent_npoints(space.get());
    if (n < 0) return false;
    out.assign(static_cast<std::size_t>(n), 0.0);
    return H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) >= 0;
  }

  const Options& o_;
  int rank_, ranks_;
  int around_ = 0;
  std::size_t nodes_ = 0, elements_ = 0;
  double partition_seconds_ = 0.0;
  std::array<std::vector<std::vector<Run>>, 2> runs_;  // [nodes, elements][rank]
  std::array<std::vector<double>, kFields.size()> data_;
  std::array<std::vector<std::size_t>, 2> rank_rows_;  // gathered: rows each rank sends, [nodes, elements][rank]
  std::vector<double> send_, receive_;
  std::array<std::array<Id, 2>, 2> selections_;       // parallel: [nodes, elements][width 1, 3]
  Id collective_;
};

std::string times(const std::vector<Phases>& all) {
  std::string s;
  for (const Phases& p : all) s += fmt::format("{}{:.0f}", s.empty() ? "" : ", ", 1e3 * p.total());
  return s;
}

// Returns false when the files do not hold what was written.
bool run_size(const Options& o, long long target, int rank, int ranks) {
  Bench b(o, target, rank, ranks);
  std::size_t max_node_runs = 0, max_element_runs = 0;
  for (int r = 0; r < ranks; ++r) {
    max_node_runs = std::max(max_node_runs, b.runs(true)[static_cast<std::size_t>(r)].size());
    max_element_runs = std::max(max_element_runs, b.runs(false)[static_cast<std::size_t>(r)].size());
  }
  if (rank == 0) {
    std::string rows;
    for (int r = 0; r < ranks; ++r)
      rows += fmt::format("{}{}/{}", r == 0 ? "" : " ", rows_in(b.runs(true)[static_cast<std::size_t>(r)]),
                          rows_in(b.runs(false)[static_cast<std::size_t>(r)]));
    fmt::print("# tube {} x {}: {} nodes, {} shells, {:.1f} MB per frame; {} ranks (METIS {:.1f} s); owned "
               "nodes/elements per rank {}; most runs of consecutive owned rows in a rank: {} of nodes, {} of "
               "elements\n",
               b.around(), b.around(), b.nodes(), b.elements(), b.frame_bytes() / 1e6, ranks, b.partition_seconds(),
               rows, max_node_runs, max_element_runs);
    std::fflush(stdout);
  }
  constexpr std::array<const char*, 3> kNames{"gathered", "gathered_fsync", "parallel"};
  std::array<std::filesystem::path, 3> paths;
  std::array<Id, 3> files;
  std::array<double, 3> open{}, close{};
  std::array<std::vector<Phases>, 3> phases;
  if (o.strategies[0] || o.strategies[1]) b.prepare_gathered();
  if (o.strategies[2]) b.prepare_parallel();
  for (std::size_t k = 0; k < 3; ++k) {
    if (!o.strategies[k]) continue;
    paths[k] = o.dir / fmt::format("{}_{}_{}.h5", kNames[k], ranks, b.nodes());
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    if (k == 2) files[k] = b.create_file(paths[k], true);
    else if (rank == 0) files[k] = b.create_file(paths[k], false);
    MPI_Barrier(MPI_COMM_WORLD);
    open[k] = MPI_Wtime() - t0;
  }
  // The strategies' frames alternate, so that a change of the machine's load falls on all of them.
  for (int frame = 0; frame < o.frames; ++frame) {
    b.fill(frame);
    for (std::size_t k = 0; k < 3; ++k)
      if (o.strategies[k])
        phases[k].push_back(k == 2 ? b.write_parallel(files[k].get(), frame)
                                   : b.write_gathered(files[k].get(), frame, k == 1));
  }
  for (std::size_t k = 0; k < 3; ++k) {
    if (!o.strategies[k]) continue;
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    files[k].reset();
    MPI_Barrier(MPI_COMM_WORLD);
    close[k] = MPI_Wtime() - t0;
  }

  int good = 1;
  if (rank == 0) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (!o.strategies[k]) continue;
      const std::string check = b.compare(paths[k]);
      if (!check.empty()) good = 0;
      const Phases best = *std::min_element(phases[k].begin(), phases[k].end(), [](const Phases& x, const Phases& y) {
        return x.total() < y.total();
      });
      fmt::print("| {} | {} | {} | {:.1f} | {} | {:.1f} ({}) | {:.1f} / {:.1f} / {:.1f} | {:.0f} | {:.0f} / {:.0f} | "
                 "{} |\n",
                 ranks, b.nodes(), b.elements(), b.frame_bytes() / 1e6, kNames[k], 1e3 * best.total(),
                 times(phases[k]), 1e3 * best.gather, 1e3 * best.write, 1e3 * best.flush,
                 b.frame_bytes() / 1e6 / best.total(), 1e3 * open[k], 1e3 * close[k],
                 check.empty() ? "bit for bit" : "DIFFERENT: " + check);
      std::fflush(stdout);
      if (!o.keep) std::filesystem::remove(paths[k]);
    }
  }
  MPI_Bcast(&good, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return good != 0;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  int code = 0;
  try {
    const Options o = parse(argc, argv);
    if (rank == 0) {
      std::filesystem::create_directories(o.dir);
      fmt::print("# h5_write_strategies: {} ranks, {} frames per strategy, files in {}{}\n", ranks, o.frames,
                 o.dir.string(), o.no_times ? " (no object times)" : "");
      fmt::print("| ranks | nodes | elements | MB per frame | strategy | best frame [ms] (all) | gather / write / flush "
                 "[ms] | MB/s | open / close [ms] | check |\n|---|---|---|---|---|---|---|---|---|---|\n");
      std::fflush(stdout);
    }
    MPI_Barrier(MPI_COMM_WORLD);
    for (const long long n : o.nodes)
      if (!run_size(o, n, rank, ranks)) code = 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "h5_write_strategies (rank {}): {}\n", rank, e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
  return code;
}
