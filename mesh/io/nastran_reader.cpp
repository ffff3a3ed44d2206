// Nastran bulk data reading (nastran_io.hpp), entry by entry
// (nastran_cards): grid points, elements, and the grid points that loads
// and constraints name, kept by the file's ids for nastran_resolve.cpp. The
// deck's text is kept as read, the GRID entries apart so that the writer
// can rewrite those of moved nodes.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <sstream>

#include "mesh/errors.hpp"
#include "mesh/second_order.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/nastran_fields.hpp"
#include "mesh/io/nastran_io.hpp"
#include "mesh/io/nastran_reader.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace nastran {
namespace {

// The comment that keeps pins no entry keeps (nastran_io.hpp), for messages.
constexpr const char* kPinnedEntry = "$TETSMOOTH PINNED";

// Data fields a GRID has (ID CP X1 X2 X3 CD PS SEID) and a CTETRA (EID PID
// G1 .. G10).
constexpr std::size_t kGridFields = 8, kTetFields = 12;
// Nastran ids have at most 8 digits: what a rewritten GRID's 16 columns hold.
constexpr long long kLargestId = 99999999;

void add_once(std::vector<std::string>& list, const std::string& item) {
  if (std::find(list.begin(), list.end(), item) == list.end()) list.push_back(item);
}

// A PID field: blank is 0.
int pid_field(const std::string& field, const Place& at) {
  long long pid = 0;
  if (!field.empty() && (!parse_integer(field, pid) || pid < 0 || pid > INT32_MAX))
    throw InputError(at.where(), "expected a property id (PID), found " + quoted_token(field));
  return static_cast<int>(pid);
}

// Data a field past an entry's last would hold is not silently dropped: a
// value there is a line laid out wrong (a large-field line continued in
// small field, a short free-field line with a continuation).
// A PS field: blank, 0, or distinct digits 1 to 6.
bool components(const std::string& field) {
  if (field.empty() || field == "0") return true;
  std::string digits = field;
  std::sort(digits.begin(), digits.end());
  return digits.size() <= 6 && digits.front() >= '1' && digits.back() <= '6' &&
         std::adjacent_find(digits.begin(), digits.end()) == digits.end();
}

void check_no_more(const Card& card, std::size_t fields, const std::string& what, const Place& at) {
  for (std::size_t d = fields; d < card.fields.size(); ++d)
    if (!card.fields[d].empty())
      throw InputError(at.where(), what + " has " + quoted_token(card.fields[d]) + " past its last field (field " +
                                       std::to_string(d % 8 + 2) + " of its line " + std::to_string(d / 8 + 1) +
                                       "): a large-field entry goes on on lines that start with '*', and each line "
                                       "of an entry holds 8 fields");
}

}  // namespace

void DeckReader::keep(const std::string& text, bool grid) {
  if (grid != kept_grids_ && !kept_.empty()) {
    mesh_.extras.raw_sections.emplace_back(kept_grids_ ? "nastran:grids" : "nastran:text", std::move(kept_));
    kept_.clear();
  }
  kept_grids_ = grid;
  kept_ += text;
}

void DeckReader::grid(const Card& card) {
  const Place at{cards_, card.mark};
  const long long id = id_field(card.field(0), "a grid point id", at);
  const std::string name = "GRID " + std::to_string(id);
  if (id > kLargestId) throw InputError(at.where(), name + ": Nastran ids have at most 8 digits");
  check_no_more(card, kGridFields, name, at);
  if (const std::string& cp = card.field(1); !cp.empty() && cp != "0")
    throw InputError(at.where(), name + " is given in coordinate system " + text_excerpt(cp) +
                                     ": nodes in other coordinate systems than the basic one are not read");
  for (std::size_t c = 0; c < 3; ++c) {
    double v = 0;  // a blank coordinate is 0
    const std::string& f = card.field(2 + c);
    if (!f.empty() && !parse_real_field(f, v))
      throw InputError(at.where(), name + ": expected a finite coordinate, found " + quoted_token(f));
    mesh_.xyz.push_back(v);
  }
  // What the writer copies when it rewrites the entry must be what Nastran
  // reads there: CD and SEID ids, PS component digits.
  for (const std::size_t d : {std::size_t{5}, std::size_t{7}})
    if (long long v = 0; !card.field(d).empty() && (!parse_integer(card.field(d), v) || v < -1 || v > kLargestId))
      throw InputError(at.where(), name + ": expected " + (d == 5 ? "a coordinate system id (CD)" : "a SEID") +
                                       ", found " + quoted_token(card.field(d)));
  if (!components(card.field(6)))
    throw InputError(at.where(), name + ": expected the components of a permanent constraint (PS: digits 1 to 6), "
                                        "found " + quoted_token(card.field(6)));
  mesh_.extras.node_tags.push_back(id);
  node_marks_.push_back(card.mark);
  const std::string& ps = card.field(6);
  grid_bits_.push_back(static_cast<std::uint8_t>((ps.empty() ? kPsBlank : ps != "0" ? kPsGiven : 0) |
                                                 (card.field(1).empty() ? kCpBlank : 0)));
}

void DeckReader::tet(const Card& card) {
  const Place at{cards_, card.mark};
  const long long id = id_field(card.field(0), "an element id", at);
  check_no_more(card, kTetFields, "CTETRA " + std::to_string(id), at);
  // A 4-node CTETRA may give its midside fields as 0.
  const auto given = [&](std::size_t k) {
    const std::string& f = card.field(2 + k);
    return !f.empty() && !(k >= 4 && f == "0");
  };
  int listed = 0;
  for (std::size_t k = 0; k < 10; ++k) listed += given(k);
  const bool four = listed == 4 && std::all_of(card.fields.begin() + 2, card.fields.begin() + 6,
                                               [](const std::string& f) { return !f.empty(); });
  if (!four && listed != 10)
    throw InputError(at.where(), "CTETRA " + std::to_string(id) + " lists " + std::to_string(listed) +
                                     " grid points" + (listed == 4 ? " with a gap before G4" : "") +
                                     ": a CTETRA has G1 to G4, or G1 to G10 with its midside nodes");
  if (tet_nodes_each_ != 0 && tet_nodes_each_ != listed) throw InputError(at.where(), mixed_tet_kinds(listed));
  tet_nodes_each_ = listed;
  for (std::size_t k = 0; k < static_cast<std::size_t>(listed); ++k)
    tet_grids_.push_back(id_field(card.field(2 + k), "a grid point id", at));
  mesh_.extras.tet_element_tags.push_back(id);
  mesh_.extras.tet_tags.push_back(pid_field(card.field(1), at));
  tet_marks_.push_back(card.mark);
  element_ids_.push_back(id);
  element_marks_.push_back(card.mark);
}

void DeckReader::pins(const EntryType& type, const Card& card) {
  for (const auto& [first, last] : grid_ranges(type, card, cards_))
    pin_refs_.push_back(PinRef{first, last, type.name, card.mark});
  orientation_pin(type, card);
}

void DeckReader::orientation_pin(const EntryType& type, const Card& card) {
  // The orientation node of a bar, beam, bush or gap (or of their defaults,
  // BAROR and BEAMOR), where a whole number gives one rather than a vector.
  if (long long g0 = 0; type.orientation >= 0 &&
                        parse_integer(card.field(static_cast<std::size_t>(type.orientation)), g0) && g0 > 0)
    pin_refs_.push_back(PinRef{g0, g0, type.name, card.mark});
}

void DeckReader::element(const EntryType& type, const Card& card) {
  const Place at{cards_, card.mark};
  const long long id = id_field(card.field(0), "an element id", at);
  element_ids_.push_back(id);
  element_marks_.push_back(card.mark);
  orientation_pin(type, card);
  // A shape other formats have: its first shape_grids fields given, no more.
  bool shaped = type.kind != nullptr;
  for (int k = 0; shaped && k < type.count; ++k)
    shaped = card.field(static_cast<std::size_t>(type.first + k)).empty() == (k >= type.shape_grids);
  if (!shaped) {
    add_once(uncarried_, type.name);
    for (const auto& [first, last] : grid_ranges(type, card, cards_))
      pin_refs_.push_back(PinRef{first, last, type.name, card.mark});
    return;
  }
  auto it = std::find_if(others_.begin(), others_.end(), [&](const Others& o) { return o.kind == type.kind; });
  if (it == others_.end())
    it = others_.insert(others_.end(), Others{type.kind, type.shape_grids, type.has_pid, {}, {}, {}, {}});
  it->tagged = it->tagged && type.has_pid;
  it->ids.push_back(id);
  for (int k = 0; k < type.shape_grids; ++k)
    it->grids.push_back(id_field(card.field(static_cast<std::size_t>(type.first + k)), "a grid point id", at));
  it->pids.push_back(type.has_pid ? pid_field(card.field(1), at) : 0);
  it->marks.push_back(card.mark);
}

void DeckReader::pinned_comment(const std::string& line) {
  const std::optional<std::string> listed = pinned_comment_ids(line);
  if (!listed) return;
  std::istringstream ids(*listed);
  const Place at{cards_, cards_.text_mark()};
  for (std::string token; ids >> token;) {
    const long long id = id_field(token, "a grid point id", at);
    pin_refs_.push_back(PinRef{id, id, kPinnedEntry, at.mark});
  }
}

void DeckReader::entry(const Card& card) {
  if (card.name == "CTETRA" || card.name == "CTETRA_") {
    meshio_tets_ = meshio_tets_ || card.name == "CTETRA_";
    return tet(card);
  }
  const EntryType* type = entry_type(card.name);
  if (type != nullptr && type->element) return element(*type, card);
  add_once(types_, text_excerpt(card.name));
  if (type != nullptr) return pins(*type, card);
  if (card.name == "SPOINT" || card.name == "EPOINT") {
    const std::vector<std::pair<long long, long long>> ids =
        grid_ranges(scalar_point_type(), card, cards_, "a scalar point id");
    scalar_points_.insert(scalar_points_.end(), ids.begin(), ids.end());
  } else if (card.name == "GRDSET") {
    grdset_cp_ = card.field(1);
    grdset_ps_ = card.field(6);
    grdset_mark_ = card.mark;
  } else if (names_grids_unread(card.name)) {
    add_once(unread_, card.name);
  } else if (!names_no_grids(card.name)) {
    add_once(unknown_, text_excerpt(card.name));
  }
}

void DeckReader::keep_notes() {
  FileExtras& e = mesh_.extras;
  stamp_kept_deck(mesh_, "nastran");
  if (!types_.empty()) e.raw_sections.emplace_back("nastran:types", joined(types_));
  if (!uncarried_.empty()) e.raw_sections.emplace_back("nastran:uncarried", joined(uncarried_));
  if (!cards_.included().empty()) e.raw_sections.emplace_back("nastran:includes", joined(cards_.included()));
  if (!unread_.empty())
    e.read_notes.push_back("the deck's " + joined(unread_) +
                           " entries name grid points that tetsmooth does not read, so their nodes are not pinned: "
                           "list those that must stay on a \"$TETSMOOTH PINNED <id> ...\" comment line");
  if (!unknown_.empty())
    e.read_notes.push_back("the deck's " + joined(unknown_) +
                           " entries are not read: where they name grid points, their nodes are not pinned (list "
                           "those that must stay on a \"$TETSMOOTH PINNED <id> ...\" comment line)");
  if (cards_.bulk_unended())
    e.read_notes.push_back(
        "the deck has BEGIN BULK but ends without ENDDATA, as a deck cut short would: check that "
        "its last entries are all there");
  if (meshio_tets_)
    e.read_notes.push_back("CTETRA_ entries (meshio 5's name for 10-node tets, which Nastran does not know) were "
                           "read as CTETRA");
}

TetMesh DeckReader::read() {
  for (BulkCards::Kind kind; (kind = cards_.next()) != BulkCards::Kind::End;) {
    if (kind == BulkCards::Kind::Text) {
      if (cards_.bulk_comment()) pinned_comment(cards_.text());
      keep(cards_.text(), false);
      continue;
    }
    const Card& card = cards_.card();
    const bool is_grid = card.name == "GRID";
    keep(card.text, is_grid);
    if (is_grid)
      grid(card);
    else
      entry(card);
  }
  keep("", !kept_grids_);  // the last piece
  if (mesh_.num_nodes() == 0) throw InputError(source_, "no GRID entries: not a Nastran mesh");
  if (tet_marks_.empty()) throw InputError(source_, "no CTETRA elements: a volume mesh of tets is needed");
  resolve();
  keep_notes();
  validate_mesh(mesh_, source_);
  return std::move(mesh_);
}

}  // namespace nastran

TetMesh read_nastran(std::istream& in, const std::string& source) {
  nastran::BulkCards cards(in, source);
  return nastran::DeckReader(cards, source).read();
}

TetMesh read_nastran_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_nastran(in, path);
}

}  // namespace tetsmooth
