#include "mesh/io/netcdf_classic_header.hpp"

#include <algorithm>
#include <cstdint>
#include <set>
#include <vector>

#include "mesh/errors.hpp"

namespace tetsmooth::netcdf {
namespace {

// The tags of the header's three lists.
constexpr std::uint32_t kDimensionTag = 10, kVariableTag = 11, kAttributeTag = 12;
// netCDF's limits: a name's length, and the dimensions of one variable.
constexpr std::uint64_t kMaxName = 256, kMaxVariableDimensions = 1024;
// numrecs of a file still being written (streaming).
constexpr std::uint64_t kStreaming32 = 0xFFFFFFFFu;
constexpr std::uint64_t kStreaming64 = 0xFFFFFFFFFFFFFFFFu;

// The size of one value of each type (0: not a type of this version).
std::uint64_t type_size(std::uint32_t type, int version) {
  switch (type) {
    case 1:  // byte
    case 2:  // char
      return 1;
    case 3:  // short
      return 2;
    case 4:  // int
    case 5:  // float
      return 4;
    case 6:  // double
      return 8;
    case 7:  // unsigned byte
      return version == 5 ? 1 : 0;
    case 8:  // unsigned short
      return version == 5 ? 2 : 0;
    case 9:  // unsigned int
      return version == 5 ? 4 : 0;
    case 10:  // 64-bit int
    case 11:  // unsigned 64-bit int
      return version == 5 ? 8 : 0;
    default:
      return 0;
  }
}

std::uint64_t padded(std::uint64_t n) { return (n + 3) / 4 * 4; }

class HeaderCheck {
 public:
  HeaderCheck(const std::string& bytes, const std::string& source)
      : bytes_(bytes), source_(source), version_(static_cast<unsigned char>(bytes.size() > 3 ? bytes[3] : 0)) {}

  void run() {
    if (bytes_.size() < 4 || bytes_.compare(0, 3, "CDF") != 0 || (version_ != 1 && version_ != 2 && version_ != 5))
      fail(0, "not a classic netCDF file");
    at_ = 4;
    numrecs_ = count();
    // netCDF 4.9 takes a streaming count for 2^32 - 1 records (and pads a
    // file written back to them).
    if (numrecs_ == (version_ == 5 ? kStreaming64 : kStreaming32))
      fail(4, "the record count is that of a file still being written (streaming)");
    dimensions();
    attributes("");
    variables();
  }

 private:
  [[noreturn]] void fail(std::uint64_t at, const std::string& what) const {
    throw InputError(source_,
                     "byte " + std::to_string(at) + ": " + what + " (the netCDF header is corrupt or cut short)");
  }

  std::uint64_t left() const { return bytes_.size() - at_; }

  std::uint64_t read(int size) {
    if (left() < static_cast<std::uint64_t>(size)) fail(at_, "the header ends early");
    std::uint64_t v = 0;
    for (int k = 0; k < size; ++k) v = v << 8 | static_cast<unsigned char>(bytes_[at_ + static_cast<std::size_t>(k)]);
    at_ += static_cast<std::size_t>(size);
    return v;
  }
  std::uint64_t count() { return read(version_ == 5 ? 8 : 4); }
  std::uint32_t tag() { return static_cast<std::uint32_t>(read(4)); }

  // A list's header: its tag and its length, at least `smallest` bytes an
  // element (so that no count runs past the file); 0 for an absent list.
  std::uint64_t list(std::uint32_t expected, std::uint64_t smallest, const char* what) {
    const std::size_t start = at_;
    const std::uint32_t t = tag();
    const std::uint64_t n = count();
    if (t == 0 && n == 0) return 0;
    if (t != expected) fail(start, std::string("the ") + what + " list has tag " + std::to_string(t));
    if (n > left() / smallest)
      fail(start, std::string("the ") + what + " list counts " + std::to_string(n) + " entries");
    return n;
  }

  std::string name(std::set<std::string>& seen, const char* what) {
    const std::size_t start = at_;
    const std::uint64_t length = count();
    if (length == 0 || length > kMaxName)
      fail(start, std::string("a ") + what + " name of " + std::to_string(length) + " bytes");
    if (padded(length) > left()) fail(start, std::string("a ") + what + " name runs past the end");
    std::string n = bytes_.substr(at_, length);
    if (n.find('\0') != std::string::npos) fail(start, std::string("a ") + what + " name holds a zero byte");
    at_ += static_cast<std::size_t>(padded(length));
    if (!seen.insert(n).second) fail(start, std::string("two ") + what + "s are named '" + n + "'");
    return n;
  }

  void dimensions() {
    const std::uint64_t n = list(kDimensionTag, 8, "dimension");
    std::set<std::string> names;
    for (std::uint64_t d = 0; d < n; ++d) {
      name(names, "dimension");
      const std::size_t start = at_;
      const std::uint64_t length = count();
      if (length == 0 && record_dimension_ >= 0) fail(start, "a second unlimited dimension");
      if (length == 0) record_dimension_ = static_cast<long long>(d);
      lengths_.push_back(length);
    }
  }

  // An attribute list: the file's (`owner` empty) or a variable's
  // ("variable 'v'").
  void attributes(const std::string& owner) {
    const std::uint64_t n = list(kAttributeTag, 12, "attribute");
    std::set<std::string> names;
    for (std::uint64_t a = 0; a < n; ++a) {
      name(names, "attribute");
      const std::size_t start = at_;
      const std::uint64_t size = type_size(tag(), version_);
      if (size == 0)
        fail(start,
             owner.empty() ? "an attribute of an unknown type" : "an attribute of " + owner + " has an unknown type");
      const std::uint64_t values = count();
      if (values > left() / size || padded(values * size) > left())
        fail(start, owner.empty() ? "an attribute's values run past the end"
                                  : "an attribute of " + owner + " runs past the end");
      at_ += static_cast<std::size_t>(padded(values * size));
    }
  }

  void variables() {
    const std::uint64_t n = list(kVariableTag, 16, "variable");
    std::set<std::string> names;
    struct Data {
      std::string name;
      std::size_t at;
      std::uint64_t begin, slab;
      bool record;
    };
    std::vector<Data> data;
    std::uint64_t record_size = 0;
    for (std::uint64_t v = 0; v < n; ++v) {
      const std::string var = name(names, "variable");
      const std::size_t start = at_;
      const std::uint64_t rank = count();
      if (rank > kMaxVariableDimensions || rank > left() / 4)
        fail(start, "variable '" + var + "' has " + std::to_string(rank) + " dimensions");
      std::uint64_t values = 1;
      bool record = false, overflow = false;
      for (std::uint64_t k = 0; k < rank; ++k) {
        const std::size_t id_at = at_;
        const std::uint64_t id = count();
        if (id >= lengths_.size())
          fail(id_at, "variable '" + var + "' names dimension " + std::to_string(id) + ", which is not defined");
        if (static_cast<long long>(id) == record_dimension_) {
          if (k != 0) fail(id_at, "variable '" + var + "' has the unlimited dimension other than first");
          record = true;
          continue;
        }
        const std::uint64_t length = lengths_[static_cast<std::size_t>(id)];
        overflow = overflow || (length != 0 && values > UINT64_MAX / length);
        values *= length;
      }
      attributes("variable '" + var + "'");
      const std::size_t type_at = at_;
      const std::uint64_t size = type_size(tag(), version_);
      if (size == 0) fail(type_at, "variable '" + var + "' has an unknown type");
      count();  // vsize, which netCDF recomputes
      const std::uint64_t begin = read(version_ == 1 ? 4 : 8);
      if (overflow || values > UINT64_MAX / size) fail(start, "variable '" + var + "' is larger than any file");
      data.push_back(Data{var, start, begin, values * size, record});
      if (record) record_size += padded(values * size);
    }
    // One record variable alone is not padded within its records.
    std::size_t record_variables = 0;
    for (const Data& d : data) record_variables += d.record;
    if (record_variables == 1)
      for (const Data& d : data)
        if (d.record) record_size = d.slab;
    const std::uint64_t size = bytes_.size();
    const Data* first_record = nullptr;
    for (const Data& d : data)
      if (d.record && first_record == nullptr) first_record = &d;
    for (const Data& d : data) {
      // Without records, netCDF places the record variables after the end
      // of the file, the first of them at that end (padded to 4 bytes): a
      // file written back is padded to it.
      const bool unplaced = d.record && numrecs_ == 0 && &d != first_record;
      bool past = d.begin < at_ || (d.begin > (d.record && numrecs_ == 0 ? padded(size) : size) && !unplaced);
      if (!d.record) {
        past = past || d.slab > size - std::min(d.begin, size);
      } else if (numrecs_ > 0) {
        const std::uint64_t last = numrecs_ - 1;
        past = past || (record_size != 0 && last > (size - std::min(d.begin, size)) / record_size) ||
               d.slab > size - std::min(d.begin + last * record_size, size);
      }
      if (past)
        fail(d.at,
             "the data of variable '" + d.name + "' lie outside the file, which ends at byte " + std::to_string(size));
    }
    // No two variables' data overlap (a write to one would change the
    // other): the fixed variables one after another, then the record
    // variables' slabs, one after another within a record.
    std::vector<const Data*> order;
    for (const Data& d : data)
      if (d.slab > 0 && (!d.record || numrecs_ > 0)) order.push_back(&d);
    std::stable_sort(order.begin(), order.end(), [](const Data* a, const Data* b) {
      return a->record != b->record ? !a->record : a->begin < b->begin;
    });
    for (std::size_t k = 1; k < order.size(); ++k) {
      const Data& before = *order[k - 1];
      const Data& d = *order[k];
      if (d.begin < before.begin + before.slab)
        fail(d.at, "the data of variables '" + before.name + "' and '" + d.name + "' overlap");
    }
    if (!order.empty() && order.front()->record && order.back()->record && record_size != 0 &&
        order.back()->begin + order.back()->slab > order.front()->begin + record_size)
      fail(order.back()->at, "the record variables' data overlap from one record to the next");
  }

  const std::string& bytes_;
  const std::string& source_;
  int version_;
  std::size_t at_ = 0;
  std::uint64_t numrecs_ = 0;
  long long record_dimension_ = -1;
  std::vector<std::uint64_t> lengths_;
};

}  // namespace

void check_classic_header(const std::string& bytes, const std::string& source) { HeaderCheck(bytes, source).run(); }

}  // namespace tetsmooth::netcdf
