#pragma once
// A netCDF dataset held in memory, the container of Exodus II files, over
// the netCDF C library (Debian: libnetcdf-dev); not a public API.
//
// Datasets are read from the bytes of a file and written to bytes, so that
// the writers can hand them to write_atomically like any other format.
// Every failure names the dataset (`source`), the variable or dimension, and
// netCDF's own reason.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace tetsmooth::netcdf {

// Which of netCDF's file formats a file's first bytes are: "CDF-1" (classic),
// "CDF-2" (64-bit offset), "CDF-5" (64-bit data), "netCDF-4" (HDF5), or ""
// for none.
std::string format_of(const std::string& bytes);

class Dataset {
 public:
  // Opens `bytes` (a whole file) for reading; InputError naming `source`
  // when netCDF cannot. netCDF reads from `bytes` itself, which must outlive
  // the dataset and not change.
  Dataset(const std::string& bytes, std::string source);
  ~Dataset();
  Dataset(const Dataset&) = delete;
  Dataset& operator=(const Dataset&) = delete;

  const std::string& source() const { return source_; }
  // The length of a dimension, or nothing when the file has none of that name.
  std::optional<std::size_t> dimension(const std::string& name) const;
  bool has_variable(const std::string& name) const;
  // The variable's lengths along its dimensions, and the dimensions' names.
  std::vector<std::size_t> shape(const std::string& name) const;
  std::vector<std::string> dimension_names(const std::string& name) const;
  // How many variables the file has.
  std::size_t variable_count() const;
  // The size of the variable's values where they are reals: 4 (float) or
  // 8 (double); 0 for any other type.
  int real_bytes(const std::string& name) const;
  // A whole variable, converted: reals, or whole numbers (InputError for a
  // real variable read as whole numbers; ints: for numbers past 32-bit ints).
  // A variable is read only where the file can hold it (check_size).
  std::vector<double> reals(const std::string& name) const;
  std::vector<long long> integers(const std::string& name) const;
  std::vector<int> ints(const std::string& name) const;
  // Throws InputError unless `values` values of `value_bytes` bytes each
  // could come from a file of this length: at most its length in a
  // classic file, and at most about 1,000 times it in a netCDF-4 file
  // (deflate's best ratio), so that a small file cannot ask for gigabytes.
  void check_size(const std::string& what, std::size_t values, std::size_t value_bytes) const;
  // A 2-D character variable as one string a row, each ending at its first
  // zero byte and without trailing blanks.
  std::vector<std::string> rows_of_text(const std::string& name) const;
  // A text attribute of a variable, or nothing.
  std::optional<std::string> text_attribute(const std::string& variable, const std::string& name) const;
  // The names of every variable, in the order of their ids, and of every
  // dimension.
  std::vector<std::string> variable_names() const;
  std::vector<std::string> all_dimension_names() const;

 private:
  int id_of(const std::string& name) const;
  std::vector<int> dimension_ids(const std::string& name) const;
  // Checks the variable's declared size (check_size) and that it holds
  // whole numbers; its element count.
  std::size_t whole_numbers_of(const std::string& name, int var) const;
  [[noreturn]] void fail(const std::string& what, int status) const;

  std::string source_;
  std::size_t largest_bytes_ = 0;  // the most data check_size lets a variable have
  int ncid_ = -1;
};

// Writes each (variable, values) pair over the variable of that name in the
// netCDF file `bytes`, converted to the variable's type, and returns the
// file as it then is: nothing else in it changes. OutputError when netCDF
// cannot, or a variable is missing or of another size.
std::string overwrite_reals(const std::string& bytes,
                            const std::vector<std::pair<std::string, const std::vector<double>*>>& values);

// A new dataset written in memory.
class NewDataset {
 public:
  // `large` picks the 64-bit data format (CDF-5), for variables of 4 GiB or
  // more; else the 64-bit offset format (CDF-2), which every Exodus reader takes.
  explicit NewDataset(bool large);
  ~NewDataset();
  NewDataset(const NewDataset&) = delete;
  NewDataset& operator=(const NewDataset&) = delete;

  // 0 for the unlimited dimension.
  int define_dimension(const std::string& name, std::size_t length);
  // `type` is an nc_type (NC_INT, NC_DOUBLE, NC_CHAR, ...).
  int define_variable(const std::string& name, int type, const std::vector<int>& dimensions);
  void text_attribute(int variable, const std::string& name, const std::string& value);  // -1: global
  void int_attribute(int variable, const std::string& name, int value);
  void float_attribute(int variable, const std::string& name, float value);
  // Ends the definitions; the puts follow.
  void end_definitions();
  void put(int variable, const std::vector<double>& values);
  void put(int variable, const std::vector<int>& values);
  // Rows of text, each cut to the row length less one and padded with zeros.
  void put_rows(int variable, const std::vector<std::string>& rows, std::size_t row_length);
  // Closes the dataset and returns the file's bytes.
  std::string bytes();

 private:
  void check(int status, const std::string& what) const;
  int ncid_ = -1;
};

}  // namespace tetsmooth::netcdf
