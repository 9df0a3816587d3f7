// results.h5: the sweep's results as HDF5 columns (libhdf5's C API; h5py or
// any HDF5 reader opens it without this project). One extendible, chunked
// dataset per column under the root group, appended chunk by chunk.
#include <hdf5.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "aurora_sweep/chunk_store.h"
#include "aurora_sweep/result_columns.h"
#include "aurora_sweep/results.h"

namespace aurora_sweep {

namespace {

constexpr hsize_t kRowsPerChunk = 1 << 16;  // HDF5 storage chunk (rows)
// Rows buffered before a write: whole storage chunks, so HDF5 never reads a
// partly written chunk back (appends of a sweep chunk's rows alone ran 4x
// slower); at most about 26 MB of columns.
constexpr size_t kFlushRows = 4 * kRowsPerChunk;

struct Column {
  const char* name;
  hid_t type;      // memory and file type (native)
  size_t size;     // bytes per value
  hid_t dataset = -1;
  std::vector<unsigned char> buffer;  // rows not written yet, `size` bytes each
};

// A result column's HDF5 column (result_columns.h).
Column columnOf(const ResultColumn& c) {
  switch (c.type) {
    case ColumnType::kFlag: return Column{c.name, H5T_NATIVE_UINT8, 1};
    case ColumnType::kDouble: return Column{c.name, H5T_NATIVE_DOUBLE, 8};
    case ColumnType::kInt32: return Column{c.name, H5T_NATIVE_INT32, 4};
    case ColumnType::kFloat: break;
  }
  return Column{c.name, H5T_NATIVE_FLOAT, 4};
}

class Hdf5Writer : public ResultsWriter {
 public:
  Hdf5Writer(const std::string& path, const SweepSpec& spec, bool feasible_only)
      : path_(path), grid_(spec.view()), params_(spec.columns()), results_(resultColumns(spec.formation())),
        feasible_only_(feasible_only) {
    file_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (file_ < 0) throw std::runtime_error("cannot write '" + path + "' (HDF5)");
    // index, the parameters (results.h: the delay whole), the results.
    columns_ = {{"index", H5T_NATIVE_INT64, 8}};
    for (int id : params_) {
      columns_.push_back(id == kParamDelay ? Column{spec.paramNameOf(id), H5T_NATIVE_INT64, 8}
                                           : Column{spec.paramNameOf(id), H5T_NATIVE_DOUBLE, 8});
    }
    for (int k = 0; k < results_.count; ++k) columns_.push_back(columnOf(results_[k]));
    const hsize_t zero = 0, unlimited = H5S_UNLIMITED, chunk = kRowsPerChunk;
    const hid_t space = H5Screate_simple(1, &zero, &unlimited);
    const hid_t props = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(props, 1, &chunk);
    H5Pset_obj_track_times(props, false);  // no timestamps: the same results, the same bytes
    for (Column& c : columns_) {
      c.dataset = H5Dcreate2(file_, c.name, c.type, space, H5P_DEFAULT, props, H5P_DEFAULT);
      if (c.dataset < 0) throw std::runtime_error("cannot create column '" + std::string(c.name) + "' in '" + path + "'");
    }
    H5Pclose(props);
    H5Sclose(space);
    for (Column& c : columns_) c.buffer.reserve((kFlushRows + (1 << 18)) * c.size);  // a flush plus a chunk
    writeAttribute("definition_hash", hashText(definitionHash(spec)));
    writeAttribute("sweep", spec.name);
  }

  ~Hdf5Writer() override { release(); }

  void append(long first, const std::vector<SimResult>& results) override {
    fillColumns(first, results);
    if (buffered_ >= kFlushRows) flush();
  }

  void close() override {
    flush();
    const bool ok = release();
    if (!ok) throw std::runtime_error("cannot finish writing '" + path_ + "' (HDF5)");
  }

  long rows() const override { return rows_ + static_cast<long>(buffered_); }

 private:
  // Writes the buffered rows at the end of every column, then empties them.
  void flush() {
    const hsize_t n = static_cast<hsize_t>(buffered_);
    if (n == 0) return;
    const hsize_t offset = static_cast<hsize_t>(rows_), total = offset + n;
    for (Column& c : columns_) {
      if (c.buffer.size() != n * c.size) {  // fillColumns put a value of another width here
        throw std::logic_error("column '" + std::string(c.name) + "' holds " + std::to_string(c.buffer.size()) +
                               " bytes for " + std::to_string(n) + " rows");
      }
      bool ok = H5Dset_extent(c.dataset, &total) >= 0;
      const hid_t file_space = H5Dget_space(c.dataset);
      ok = ok && H5Sselect_hyperslab(file_space, H5S_SELECT_SET, &offset, nullptr, &n, nullptr) >= 0;
      const hid_t mem_space = H5Screate_simple(1, &n, nullptr);
      ok = ok && H5Dwrite(c.dataset, c.type, mem_space, file_space, H5P_DEFAULT, c.buffer.data()) >= 0;
      H5Sclose(mem_space);
      H5Sclose(file_space);
      if (!ok) throw std::runtime_error("cannot write column '" + std::string(c.name) + "' of '" + path_ + "'");
      c.buffer.clear();
    }
    rows_ += static_cast<long>(n);
    buffered_ = 0;
  }

  // Row `row`'s value of column k (its native type, as declared).
  template <typename V>
  void put(size_t k, size_t row, V value) {
    std::memcpy(&columns_[k].buffer[row * sizeof value], &value, sizeof value);
  }
  void putValue(size_t k, size_t row, const ColumnValue& v) {
    switch (v.type) {
      case ColumnType::kFlag: return put(k, row, v.flag);
      case ColumnType::kDouble: return put(k, row, v.real);
      case ColumnType::kInt32: return put(k, row, v.whole);
      case ColumnType::kFloat: return put(k, row, v.single);
    }
  }

  // Appends the rows of one sweep chunk, in the columns' order: the buffers
  // grow once per chunk, then shrink to the rows kept.
  void fillColumns(long first, const std::vector<SimResult>& results) {
    for (Column& c : columns_) c.buffer.resize((buffered_ + results.size()) * c.size);
    for (size_t i = 0; i < results.size(); ++i) {
      const SimResult& r = results[i];
      if (feasible_only_ && !feasible(r)) continue;
      const long index = first + static_cast<long>(i);
      const Combination c = grid_.decode(index);
      const size_t row = buffered_++;
      put(0, row, int64_t(index));
      size_t col = 1;
      for (int id : params_) {
        if (id == kParamDelay) put(col++, row, int64_t(c.delay()));
        else put(col++, row, c.v[id]);
      }
      for (int k = 0; k < results_.count; ++k) putValue(col++, row, columnValue(r, results_[k]));
    }
    for (Column& c : columns_) c.buffer.resize(buffered_ * c.size);
  }

  void writeAttribute(const char* name, const std::string& value) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, value.size() + 1);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attr = H5Acreate2(file_, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(attr, type, value.c_str());
    H5Aclose(attr);
    H5Sclose(space);
    H5Tclose(type);
  }

  bool release() {
    bool ok = true;
    for (Column& c : columns_) {
      if (c.dataset >= 0) ok = H5Dclose(c.dataset) >= 0 && ok;
      c.dataset = -1;
    }
    if (file_ >= 0) ok = H5Fclose(file_) >= 0 && ok;
    file_ = -1;
    return ok;
  }

  std::string path_;
  GridView grid_;
  std::vector<int> params_;  // ParamIds of the parameter columns
  ResultColumnList results_;  // then these
  bool feasible_only_;
  hid_t file_ = -1;
  std::vector<Column> columns_;
  long rows_ = 0;        // written
  size_t buffered_ = 0;  // in the column buffers
};

}  // namespace

bool hdf5Available() { return true; }

std::unique_ptr<ResultsWriter> openHdf5Writer(const std::string& path, const SweepSpec& spec,
                                              bool feasible_only) {
  return std::unique_ptr<ResultsWriter>(new Hdf5Writer(path, spec, feasible_only));
}

}  // namespace aurora_sweep
