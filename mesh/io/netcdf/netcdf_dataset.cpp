#include "mesh/io/netcdf/netcdf_dataset.hpp"

#include <fcntl.h>
#include <netcdf.h>
#include <netcdf_mem.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "mesh/errors.hpp"
#include "mesh/io/netcdf_classic_header.hpp"
#include "mesh/io/temp_file_cleanup.hpp"

namespace tetsmooth::netcdf {
namespace {

// HDF5 (netCDF-4) files start with this signature, at byte 0 or after a
// user block of 512, 1024, 2048, ... bytes.
constexpr char kHdf5Signature[] = "\x89HDF\r\n\x1a\n";

bool hdf5_at(const std::string& bytes, std::size_t offset) {
  return bytes.size() >= offset + 8 && std::memcmp(bytes.data() + offset, kHdf5Signature, 8) == 0;
}

std::string status_text(int status) { return nc_strerror(status); }

// netCDF's reasons for a file read from memory. Its in-memory reader
// answers a read past the end of the bytes with a system error (EPERM),
// which would send the user after file permissions: the file is shorter
// than its header says.
std::string read_failure(int status) {
  return status > 0 ? "the file ends before the data its header describes (cut short?)" : status_text(status);
}

// A scratch copy of a netCDF-4 file, which netCDF can change only on disk;
// removed when done, and by an interrupting signal.
class ScratchFile {
 public:
  explicit ScratchFile(const std::string& bytes) {
    const char* dir = std::getenv("TMPDIR");
    std::string pattern = std::string(dir != nullptr && *dir != '\0' ? dir : "/tmp") + "/tetsmooth-exodus-XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    const int fd = ::mkstemp(name.data());
    if (fd < 0)
      throw OutputError("cannot make a scratch copy of the Exodus file in " + pattern + ": " + std::strerror(errno));
    ::close(fd);
    path_ = name.data();
    slot_ = remember_temp_file(path_);
    std::ofstream out(path_, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw OutputError("cannot write the scratch copy " + path_ + " of the Exodus file");
  }
  ~ScratchFile() {
    std::remove(path_.c_str());
    forget_temp_file(slot_);
  }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  const std::string& path() const { return path_; }
  std::string contents() const {
    std::ifstream in(path_, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.eof() && in.fail()) throw OutputError("cannot read back the scratch copy " + path_ + " of the Exodus file");
    return bytes;
  }

 private:
  std::string path_;
  int slot_ = -1;
};

void put_reals(int ncid, const std::vector<std::pair<std::string, const std::vector<double>*>>& values) {
  for (const auto& [name, data] : values) {
    int var = -1, dims = 0;
    if (nc_inq_varid(ncid, name.c_str(), &var) != NC_NOERR)
      throw OutputError("the kept Exodus file has no variable '" + name + "'");
    std::size_t count = 1;
    int dim_ids[NC_MAX_VAR_DIMS];
    nc_inq_varndims(ncid, var, &dims);
    nc_inq_vardimid(ncid, var, dim_ids);
    for (int d = 0; d < dims; ++d) {
      std::size_t length = 0;
      nc_inq_dimlen(ncid, dim_ids[d], &length);
      count *= length;
    }
    if (count != data->size())
      throw OutputError("the kept Exodus file's variable '" + name + "' holds " + std::to_string(count) +
                        " values, and the mesh gives " + std::to_string(data->size()));
    if (const int status = nc_put_var_double(ncid, var, data->data()); status != NC_NOERR)
      throw OutputError("cannot write the Exodus variable '" + name + "': " + status_text(status));
  }
}

// HDF5 can crash on a corrupt netCDF-4 file (1.10's global heap reader,
// reached while netCDF opens one, for instance), or loop without end (the
// same reader). A child process opens it first and asks after every
// dimension, variable and attribute, within kProbeSeconds (far more than
// any header takes), so that a crash or a loop there is a refusal here.
// Only where the child cannot be made or waited for is the file opened
// without this probe.
constexpr int kProbeSeconds = 30;

// The child: it dies with the parent, leaves no core file, writes nowhere,
// runs no handler of the parent's (temp_file_cleanup.hpp's would remove the
// parent's temporaries), and ends by itself if the parent's wait does not.
[[noreturn]] void run_probe(const std::string& bytes, pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(0);
  ::prctl(PR_SET_DUMPABLE, 0);
  const struct rlimit no_core = {0, 0};
  ::setrlimit(RLIMIT_CORE, &no_core);
  for (int sig = 1; sig < NSIG; ++sig)
    if (sig != SIGKILL && sig != SIGSTOP) ::signal(sig, SIG_DFL);
  if (const int null = ::open("/dev/null", O_RDWR); null >= 0)
    for (int fd = 0; fd <= 2; ++fd) ::dup2(null, fd);
  ::alarm(kProbeSeconds + 5);
  int ncid = -1;
  if (nc_open_mem("probe", NC_NOWRITE, bytes.size(), const_cast<char*>(bytes.data()), &ncid) == NC_NOERR) {
    char name[NC_MAX_NAME + 1];
    int dims = 0, variables = 0, globals = 0, unlimited = -1;
    nc_inq(ncid, &dims, &variables, &globals, &unlimited);
    for (int d = 0; d < dims; ++d) {
      std::size_t length = 0;
      nc_inq_dim(ncid, d, name, &length);
    }
    for (int v = NC_GLOBAL; v < variables; ++v) {
      nc_type type = NC_NAT;
      int rank = 0, attributes = globals;
      int dim_ids[NC_MAX_VAR_DIMS];
      if (v != NC_GLOBAL && nc_inq_var(ncid, v, name, &type, &rank, dim_ids, &attributes) != NC_NOERR) continue;
      for (int a = 0; a < attributes; ++a) {
        std::size_t length = 0;
        if (nc_inq_attname(ncid, v, a, name) == NC_NOERR) nc_inq_att(ncid, v, name, &type, &length);
      }
    }
    nc_close(ncid);
  }
  ::_exit(0);
}

void probe_in_child(const std::string& bytes, const std::string& source) {
  // An ignored SIGCHLD would have the child reaped unseen.
  struct sigaction previous {};
  struct sigaction reap {};
  reap.sa_handler = SIG_DFL;
  ::sigaction(SIGCHLD, &reap, &previous);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid == 0) run_probe(bytes, parent);
  int status = 0;
  bool ended = false, looped = false;
  for (int waited_ms = 0; pid > 0; waited_ms += 10) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) {
      ended = true;
      break;
    }
    if (done < 0 && errno != EINTR) break;
    if (waited_ms >= 1000 * kProbeSeconds) {
      ::kill(pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      looped = true;
      break;
    }
    ::usleep(10000);
  }
  ::sigaction(SIGCHLD, &previous, nullptr);
  if (looped)
    throw InputError(source, "the netCDF-4 (HDF5) file is corrupt: reading its header did not end in " +
                                 std::to_string(kProbeSeconds) + " s");
  if (ended && WIFSIGNALED(status))
    throw InputError(source, "the netCDF-4 (HDF5) file is corrupt: reading its header " +
                                 std::string(WTERMSIG(status) == SIGALRM ? "did not end" : "crashed HDF5") +
                                 " (signal " + std::to_string(WTERMSIG(status)) + ")");
}

}  // namespace

std::string format_of(const std::string& bytes) {
  if (bytes.size() >= 4 && bytes.compare(0, 3, "CDF") == 0) {
    switch (bytes[3]) {
      case 1:
        return "CDF-1";
      case 2:
        return "CDF-2";
      case 5:
        return "CDF-5";
      default:
        return "";
    }
  }
  for (std::size_t offset = 0; offset + 8 <= bytes.size(); offset = offset == 0 ? 512 : 2 * offset)
    if (hdf5_at(bytes, offset)) return "netCDF-4";
  return "";
}

Dataset::Dataset(const std::string& bytes, std::string source) : source_(std::move(source)) {
  const std::string format = format_of(bytes);
  // netCDF trusts a classic header (netcdf_classic_header.hpp), and HDF5
  // may crash on a corrupt one of its own (probe_in_child).
  if (format.rfind("CDF", 0) == 0)
    check_classic_header(bytes, source_);
  else
    probe_in_child(bytes, source_);
  largest_bytes_ = format.rfind("CDF", 0) == 0 ? bytes.size() : 1100 * bytes.size() + 65536;
  // Opened read-only, netCDF never writes to the memory it is given.
  const int status = nc_open_mem(source_.c_str(), NC_NOWRITE, bytes.size(), const_cast<char*>(bytes.data()), &ncid_);
  if (status != NC_NOERR) throw InputError(source_, "netCDF cannot read the file: " + read_failure(status));
}

Dataset::~Dataset() {
  if (ncid_ >= 0) nc_close(ncid_);
}

void Dataset::fail(const std::string& what, int status) const {
  throw InputError(source_, what + ": " + read_failure(status));
}

std::optional<std::size_t> Dataset::dimension(const std::string& name) const {
  int dim = -1;
  if (nc_inq_dimid(ncid_, name.c_str(), &dim) != NC_NOERR) return std::nullopt;
  std::size_t length = 0;
  if (const int status = nc_inq_dimlen(ncid_, dim, &length); status != NC_NOERR)
    fail("dimension '" + name + "'", status);
  return length;
}

bool Dataset::has_variable(const std::string& name) const {
  int var = -1;
  return nc_inq_varid(ncid_, name.c_str(), &var) == NC_NOERR;
}

int Dataset::id_of(const std::string& name) const {
  int var = -1;
  if (const int status = nc_inq_varid(ncid_, name.c_str(), &var); status != NC_NOERR)
    fail("variable '" + name + "'", status);
  return var;
}

std::vector<int> Dataset::dimension_ids(const std::string& name) const {
  const int var = id_of(name);
  int dims = 0;
  if (const int status = nc_inq_varndims(ncid_, var, &dims); status != NC_NOERR)
    fail("variable '" + name + "'", status);
  std::vector<int> ids(static_cast<std::size_t>(std::max(dims, 0)));
  if (const int status = nc_inq_vardimid(ncid_, var, ids.data()); status != NC_NOERR)
    fail("variable '" + name + "'", status);
  return ids;
}

std::vector<std::size_t> Dataset::shape(const std::string& name) const {
  std::vector<std::size_t> lengths;
  for (int id : dimension_ids(name)) {
    std::size_t length = 0;
    if (const int status = nc_inq_dimlen(ncid_, id, &length); status != NC_NOERR)
      fail("variable '" + name + "'", status);
    lengths.push_back(length);
  }
  return lengths;
}

std::vector<std::string> Dataset::dimension_names(const std::string& name) const {
  std::vector<std::string> names;
  char dim_name[NC_MAX_NAME + 1];
  for (int id : dimension_ids(name)) {
    if (const int status = nc_inq_dimname(ncid_, id, dim_name); status != NC_NOERR)
      fail("variable '" + name + "'", status);
    names.emplace_back(dim_name);
  }
  return names;
}

std::size_t Dataset::variable_count() const {
  int count = 0;
  if (const int status = nc_inq_nvars(ncid_, &count); status != NC_NOERR) fail("the variables", status);
  return static_cast<std::size_t>(count);
}

void Dataset::check_size(const std::string& what, std::size_t values, std::size_t value_bytes) const {
  if (values > largest_bytes_ / std::max<std::size_t>(value_bytes, 1))
    throw InputError(source_, what + " declares " + std::to_string(values) +
                                  " values, more than a file of its length holds (corrupt?)");
}

namespace {
// The number of values of a variable of these lengths (SIZE_MAX where it
// overflows, which check_size then refuses).
std::size_t product(const std::vector<std::size_t>& lengths) {
  std::size_t n = 1;
  for (std::size_t l : lengths) {
    if (l != 0 && n > SIZE_MAX / l) return SIZE_MAX;
    n *= l;
  }
  return n;
}
}  // namespace

int Dataset::real_bytes(const std::string& name) const {
  nc_type type = NC_NAT;
  if (const int status = nc_inq_vartype(ncid_, id_of(name), &type); status != NC_NOERR)
    fail("variable '" + name + "'", status);
  return type == NC_FLOAT ? 4 : type == NC_DOUBLE ? 8 : 0;
}

std::vector<double> Dataset::reals(const std::string& name) const {
  const int var = id_of(name);
  const std::size_t count = product(shape(name));
  check_size("variable '" + name + "'", count, std::max(real_bytes(name), 1));
  std::vector<double> values(count);
  if (values.empty()) return values;
  if (const int status = nc_get_var_double(ncid_, var, values.data()); status != NC_NOERR)
    fail("variable '" + name + "'", status);
  return values;
}

std::size_t Dataset::whole_numbers_of(const std::string& name, int var) const {
  nc_type type = NC_NAT;
  if (const int status = nc_inq_vartype(ncid_, var, &type); status != NC_NOERR) fail("variable '" + name + "'", status);
  if (type == NC_FLOAT || type == NC_DOUBLE || type == NC_CHAR || type == NC_STRING)
    throw InputError(source_, "variable '" + name + "' holds " +
                                  (type == NC_CHAR || type == NC_STRING ? "text" : "real numbers") +
                                  " where Exodus has whole numbers");
  std::size_t size = 0;
  if (const int status = nc_inq_type(ncid_, type, nullptr, &size); status != NC_NOERR)
    fail("variable '" + name + "'", status);
  const std::size_t count = product(shape(name));
  check_size("variable '" + name + "'", count, size);
  return count;
}

std::vector<long long> Dataset::integers(const std::string& name) const {
  const int var = id_of(name);
  std::vector<long long> values(whole_numbers_of(name, var));
  if (values.empty()) return values;
  if (const int status = nc_get_var_longlong(ncid_, var, values.data()); status != NC_NOERR)
    fail("variable '" + name + "'", status);
  return values;
}

std::vector<int> Dataset::ints(const std::string& name) const {
  const int var = id_of(name);
  std::vector<int> values(whole_numbers_of(name, var));
  if (values.empty()) return values;
  const int status = nc_get_var_int(ncid_, var, values.data());
  if (status == NC_ERANGE) throw InputError(source_, "variable '" + name + "' holds numbers past 32-bit ints");
  if (status != NC_NOERR) fail("variable '" + name + "'", status);
  return values;
}

std::vector<std::string> Dataset::rows_of_text(const std::string& name) const {
  const int var = id_of(name);
  const std::vector<std::size_t> lengths = shape(name);
  nc_type type = NC_NAT;
  nc_inq_vartype(ncid_, var, &type);
  if (type != NC_CHAR || lengths.size() != 2)
    throw InputError(source_, "variable '" + name + "' is not a table of text rows");
  check_size("variable '" + name + "'", product(lengths), 1);
  std::string text(lengths[0] * lengths[1], '\0');
  if (!text.empty())
    if (const int status = nc_get_var_text(ncid_, var, text.data()); status != NC_NOERR)
      fail("variable '" + name + "'", status);
  std::vector<std::string> rows;
  for (std::size_t r = 0; r < lengths[0]; ++r) {
    std::string row = text.substr(r * lengths[1], lengths[1]);
    row = row.substr(0, row.find('\0'));
    while (!row.empty() && row.back() == ' ') row.pop_back();
    rows.push_back(row);
  }
  return rows;
}

std::optional<std::string> Dataset::text_attribute(const std::string& variable, const std::string& name) const {
  const int var = id_of(variable);
  nc_type type = NC_NAT;
  std::size_t length = 0;
  if (nc_inq_att(ncid_, var, name.c_str(), &type, &length) != NC_NOERR || type != NC_CHAR) return std::nullopt;
  check_size("attribute '" + name + "' of variable '" + variable + "'", length, 1);
  std::string value(length, '\0');
  if (const int status = nc_get_att_text(ncid_, var, name.c_str(), value.data()); status != NC_NOERR)
    fail("attribute '" + name + "' of variable '" + variable + "'", status);
  return value.substr(0, value.find('\0'));
}

std::vector<std::string> Dataset::variable_names() const {
  int count = 0;
  if (const int status = nc_inq_nvars(ncid_, &count); status != NC_NOERR) fail("the variables", status);
  std::vector<std::string> names;
  char name[NC_MAX_NAME + 1];
  for (int v = 0; v < count; ++v)
    if (nc_inq_varname(ncid_, v, name) == NC_NOERR) names.emplace_back(name);
  return names;
}

std::vector<std::string> Dataset::all_dimension_names() const {
  int count = 0;
  if (const int status = nc_inq_dimids(ncid_, &count, nullptr, 0); status != NC_NOERR) fail("the dimensions", status);
  std::vector<int> ids(static_cast<std::size_t>(std::max(count, 0)));
  if (const int status = nc_inq_dimids(ncid_, &count, ids.data(), 0); status != NC_NOERR)
    fail("the dimensions", status);
  std::vector<std::string> names;
  char name[NC_MAX_NAME + 1];
  for (int id : ids)
    if (nc_inq_dimname(ncid_, id, name) == NC_NOERR) names.emplace_back(name);
  return names;
}

std::string overwrite_reals(const std::string& bytes,
                            const std::vector<std::pair<std::string, const std::vector<double>*>>& values) {
  if (format_of(bytes) == "netCDF-4") {
    // netCDF changes an HDF5 file in place only on disk.
    ScratchFile scratch(bytes);
    int ncid = -1;
    if (const int status = nc_open(scratch.path().c_str(), NC_WRITE, &ncid); status != NC_NOERR)
      throw OutputError("cannot reopen the kept Exodus file: " + status_text(status));
    try {
      put_reals(ncid, values);
    } catch (...) {
      nc_close(ncid);
      throw;
    }
    if (const int status = nc_close(ncid); status != NC_NOERR)
      throw OutputError("cannot write the kept Exodus file: " + status_text(status));
    return scratch.contents();
  }
  // A classic file is changed in memory; netCDF takes the copy given and
  // hands back the changed one, of the same length.
  NC_memio memio{};
  memio.size = bytes.size();
  memio.memory = std::malloc(bytes.empty() ? 1 : bytes.size());
  if (memio.memory == nullptr) throw OutputError("out of memory for the kept Exodus file");
  std::memcpy(memio.memory, bytes.data(), bytes.size());
  int ncid = -1;
  if (const int status = nc_open_memio("kept Exodus file", NC_WRITE, &memio, &ncid); status != NC_NOERR) {
    std::free(memio.memory);
    throw OutputError("cannot reopen the kept Exodus file: " + status_text(status));
  }
  try {
    put_reals(ncid, values);
  } catch (...) {
    NC_memio lost{};
    if (nc_close_memio(ncid, &lost) == NC_NOERR) std::free(lost.memory);
    throw;
  }
  NC_memio out{};
  if (const int status = nc_close_memio(ncid, &out); status != NC_NOERR)
    throw OutputError("cannot write the kept Exodus file: " + status_text(status));
  std::string changed(static_cast<const char*>(out.memory), out.size);
  std::free(out.memory);
  return changed;
}

NewDataset::NewDataset(bool large) {
  check(nc_create_mem("new Exodus file", large ? NC_64BIT_DATA : NC_64BIT_OFFSET, 0, &ncid_), "create the file");
}

NewDataset::~NewDataset() {
  if (ncid_ < 0) return;
  NC_memio lost{};
  if (nc_close_memio(ncid_, &lost) == NC_NOERR) std::free(lost.memory);
}

void NewDataset::check(int status, const std::string& what) const {
  if (status != NC_NOERR) throw OutputError("netCDF cannot " + what + ": " + status_text(status));
}

int NewDataset::define_dimension(const std::string& name, std::size_t length) {
  int dim = -1;
  check(nc_def_dim(ncid_, name.c_str(), length == 0 ? NC_UNLIMITED : length, &dim), "define dimension " + name);
  return dim;
}

int NewDataset::define_variable(const std::string& name, int type, const std::vector<int>& dimensions) {
  int var = -1;
  check(nc_def_var(ncid_, name.c_str(), type, static_cast<int>(dimensions.size()), dimensions.data(), &var),
        "define variable " + name);
  return var;
}

void NewDataset::text_attribute(int variable, const std::string& name, const std::string& value) {
  check(nc_put_att_text(ncid_, variable < 0 ? NC_GLOBAL : variable, name.c_str(), value.size(), value.data()),
        "write attribute " + name);
}

void NewDataset::int_attribute(int variable, const std::string& name, int value) {
  check(nc_put_att_int(ncid_, variable < 0 ? NC_GLOBAL : variable, name.c_str(), NC_INT, 1, &value),
        "write attribute " + name);
}

void NewDataset::float_attribute(int variable, const std::string& name, float value) {
  check(nc_put_att_float(ncid_, variable < 0 ? NC_GLOBAL : variable, name.c_str(), NC_FLOAT, 1, &value),
        "write attribute " + name);
}

void NewDataset::end_definitions() { check(nc_enddef(ncid_), "end the definitions"); }

void NewDataset::put(int variable, const std::vector<double>& values) {
  if (!values.empty()) check(nc_put_var_double(ncid_, variable, values.data()), "write a variable");
}

void NewDataset::put(int variable, const std::vector<int>& values) {
  if (!values.empty()) check(nc_put_var_int(ncid_, variable, values.data()), "write a variable");
}

void NewDataset::put_rows(int variable, const std::vector<std::string>& rows, std::size_t row_length) {
  std::string text(rows.size() * row_length, '\0');
  for (std::size_t r = 0; r < rows.size(); ++r)
    std::memcpy(&text[r * row_length], rows[r].data(), std::min(rows[r].size(), row_length - 1));
  if (!text.empty()) check(nc_put_var_text(ncid_, variable, text.data()), "write a variable");
}

std::string NewDataset::bytes() {
  NC_memio memio{};
  const int status = nc_close_memio(ncid_, &memio);
  ncid_ = -1;
  check(status, "finish the file");
  std::string file(static_cast<const char*>(memio.memory), memio.size);
  std::free(memio.memory);
  return file;
}

}  // namespace tetsmooth::netcdf
