// LS-DYNA keyword deck reading (lsdyna_io.hpp), line by line: nodes,
// elements, parts, and the nodes that sets, loads and constraints name,
// kept by the deck's ids for lsdyna_resolve.cpp. The deck's text is kept as
// read, the *NODE data apart so that the writer can rewrite moved nodes.
#include <algorithm>
#include <cstdint>
#include <fstream>

#include "mesh/errors.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/lsdyna_io.hpp"
#include "mesh/io/lsdyna_reader.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/second_order.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace lsdyna {
namespace {

// Keywords whose data cards name nodes in the given fields (10 columns
// each, 20 in the long layout), one card at a time.
struct NodeFieldKeyword {
  const char* name;
  std::vector<int> fields;
};
const std::vector<NodeFieldKeyword>& node_field_keywords() {
  static const std::vector<NodeFieldKeyword> table{
      {"BOUNDARY_SPC_NODE", {0}},
      {"BOUNDARY_PRESCRIBED_MOTION_NODE", {0}},
      {"LOAD_NODE_POINT", {0}},
      {"INITIAL_VELOCITY_NODE", {0}},
      {"CONSTRAINED_EXTRA_NODES_NODE", {1}},
      {"CONSTRAINED_SPOTWELD", {0, 1}},
      {"DATABASE_HISTORY_NODE", {0, 1, 2, 3, 4, 5, 6, 7}},
  };
  return table;
}

bool starts_with(const std::string& s, std::string_view prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

// *PART and its options that keep *PART's first cards (a heading, then PID
// first on the next): not *PART_SENSOR, *PART_DUPLICATE, *PART_ANNEAL,
// *PART_MODES and the like, whose cards are others.
bool is_part_keyword(const std::string& name) {
  if (name == "PART") return true;
  if (!starts_with(name, "PART_")) return false;
  static const char* const kOptions[] = {"INERTIA", "REPOSITION", "ATTACHMENT", "NODES", "CONTACT",
                                         "PRINT",   "AVERAGED",   "COMPOSITE",  "LONG",  "TSHELL"};
  for (std::size_t at = 5; at < name.size();) {
    const std::size_t end = std::min(name.find('_', at), name.size());
    const std::string_view word = std::string_view(name).substr(at, end - at);
    if (std::none_of(std::begin(kOptions), std::end(kOptions), [&](const char* o) { return word == o; })) return false;
    at = end + 1;
  }
  return true;
}

// The options after `base` in a keyword's name ("ELEMENT_SHELL_THICKNESS"
// has {"THICKNESS"}).
std::vector<std::string> options_of(const std::string& name, std::string_view base) {
  std::vector<std::string> out;
  std::size_t at = base.size();
  while (at < name.size()) {
    const std::size_t next = name.find('_', at + 1);
    out.push_back(name.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1));
    at = next == std::string::npos ? name.size() : next;
  }
  return out;
}

// Whether a keyword not read names nodes, so that its nodes may move: the
// element and constraint keywords, node keywords other than *NODE, node sets
// not read, and those with _NODE in their name. Those that name node sets
// (a SET word: *LOAD_NODE_SET), which pin their nodes anyway, and
// *SET_NODE_ADD, which names sets, are left out.
bool names_nodes(const std::string& name) {
  if (starts_with(name, "SET_NODE")) return !starts_with(name, "SET_NODE_ADD");
  const std::string words = "_" + name + "_";
  if (words.find("_SET_") != std::string::npos || name == "CONSTRAINED_NODAL_RIGID_BODY") return false;
  return starts_with(name, "ELEMENT_") || starts_with(name, "CONSTRAINED_") || starts_with(name, "NODE_") ||
         name.find("_NODE") != std::string::npos;
}

bool distinct(const long long* n, std::initializer_list<int> places) {
  for (auto a = places.begin(); a != places.end(); ++a) {
    if (n[*a] <= 0) return false;
    for (auto b = places.begin(); b != a; ++b)
      if (n[*a] == n[*b]) return false;
  }
  return true;
}

bool all_equal(const long long* n, int from, int to, long long value) {
  for (int i = from; i < to; ++i)
    if (n[i] != value) return false;
  return true;
}

void add_once(std::vector<std::string>& list, const std::string& item) {
  if (std::find(list.begin(), list.end(), item) == list.end()) list.push_back(item);
}

}  // namespace

void DeckReader::fail(const std::string& what) const { throw InputError(lines_.where(), what); }

void DeckReader::flush_kept() {
  if (kept_.empty()) return;
  const char* key = !kept_nodes_                   ? "lsdyna:text"
                    : kept_layout_ == Layout::I10  ? "lsdyna:nodes-i10"
                    : kept_layout_ == Layout::Long ? "lsdyna:nodes-long"
                                                   : "lsdyna:nodes";
  mesh_.extras.raw_sections.emplace_back(key, std::move(kept_));
  kept_.clear();
}

void DeckReader::keep(const std::string& line, bool node_data) {
  if (node_data != kept_nodes_ || (node_data && node_layout_ != kept_layout_)) flush_kept();
  kept_nodes_ = node_data;
  kept_layout_ = node_layout_;
  kept_ += line;
  kept_ += '\n';
}

long long DeckReader::id_field(std::string_view field, const char* what, bool zero_allowed) const {
  long long v = 0;
  if (!int_field(field, v) || v < 0 || (v == 0 && !zero_allowed))
    fail("expected " + std::string(what) + ", a positive whole number, found " +
         (field.empty() ? std::string("a blank field") : quoted_token(field)));
  return v;
}

int DeckReader::pid_field(std::string_view field) const {
  long long v = 0;
  if (!int_field(field, v) || v < 0) fail("expected a part id (PID), found " + quoted_token(field));
  if (v > INT32_MAX) fail("part id " + std::to_string(v) + " is past 2,147,483,647, the largest region tag");
  return static_cast<int>(v);
}

void DeckReader::keyword(const std::string& line) {
  if (section_ == Section::Solid || section_ == Section::Shell || section_ == Section::Beam ||
      section_ == Section::PinOnly)
    if (card_ != 0) fail("*" + keyword_ + ": the element before this line lacks some of its cards");
  const Keyword k = keyword_of(line);
  keyword_ = k.name;
  layout_ = k.marked ? k.layout : deck_layout_;
  section_ = Section::Other;
  card_ = 0;
  cards_each_ = 1;
  title_pending_ = head_pending_ = false;
  part_pid_card_ = 0;
  const std::string& name = keyword_;
  // An included file's *KEYWORD and its cards are written as comments
  // (written_inline).
  inline_comments_ = false;
  if (name == "KEYWORD" || name == "KEYWORD_ID") {
    const std::string options = upper_case(k.rest);
    // LONG=Y reads every keyword in the long layout (its fields, ids among
    // them, 20 columns wide: I10=Y beside it changes nothing). LONG=S and
    // LONG=K also set the layout of the files LS-DYNA writes, and no source
    // at hand said for certain which layout they read the input in: refused,
    // since a guess could misread the deck.
    for (const char* key : {"LONG=S", "LONG=K"})
      if (options.find(key) != std::string::npos)
        fail(std::string("*KEYWORD ") + key +
             " is not read: tetsmooth reads LONG=Y (every field 20 columns wide), the standard layout and "
             "I10=Y; save the deck in one of those");
    Layout asked = options.find("I10=Y") != std::string::npos ? Layout::I10 : deck_layout_;
    if (options.find("LONG=Y") != std::string::npos) asked = Layout::Long;
    if (k.marked) asked = k.layout;
    inline_comments_ = lines_.depth() > 1;
    if (lines_.depth() == 1) {
      deck_keyword_ = true;
      deck_layout_ = layout_ = asked;
    } else if (asked != deck_layout_) {
      // LS-DYNA reads an included file in the deck's layout, or in the one
      // its *INCLUDE's mark names, whatever the file's *KEYWORD says; read
      // otherwise, the file would mean something else to it.
      fail("an included file's *KEYWORD sets no layout in LS-DYNA, and this file is read in the " +
           std::string(layout_name(deck_layout_)) + " layout: mark its *INCLUDE (\"*INCLUDE " + layout_mark(asked) +
           "\") for a file in the " + layout_name(asked) + " layout");
    }
    return;
  }
  if (name == "END") {
    section_ = Section::Ended;
    deck_end_ = deck_end_ || lines_.depth() == 1;
    return;
  }
  if (name == "INCLUDE") {
    section_ = Section::Include;
    include_layout_ = layout_;  // "*INCLUDE %" ("+"): the files named are in the I10 (long) layout
    include_name_.clear();
    return;
  }
  if (starts_with(name, "INCLUDE_"))
    fail("*" + name + " is not read (tetsmooth follows plain *INCLUDE, with paths from the deck's directory)");
  if (name == "NODE_TRANSFORM" || starts_with(name, "NODE_MERGE") || name == "PART_MOVE")
    fail("*" + name + " moves or merges nodes, which tetsmooth does not do: apply it in the pre-processor first");
  if (name == "NODE") {
    section_ = Section::Node;
    node_layout_ = layout_;
  } else if (starts_with(name, "ELEMENT_SOLID")) {
    for (const std::string& o : options_of(name, "ELEMENT_SOLID")) {
      if (o == "ORTHO")
        cards_each_ += 2;
      else if (o == "DOF")
        cards_each_ += 1;
      else if (o != "TET4TOTET10")
        fail("*" + name + " is not read (tetsmooth reads *ELEMENT_SOLID with the options TET4TOTET10, ORTHO and DOF)");
    }
    section_ = Section::Solid;
  } else if (name == "ELEMENT_SHELL" || starts_with(name, "ELEMENT_SHELL_")) {
    section_ = Section::Shell;
    bool thickness = false;
    for (const std::string& o : options_of(name, "ELEMENT_SHELL")) {
      if (o == "THICKNESS" || o == "BETA" || o == "MCID")
        thickness = true;  // one card holds the thicknesses and the angle
      else if (o == "OFFSET")
        ++cards_each_;
      else
        section_ = Section::Other;
    }
    cards_each_ += thickness;
  } else if (name == "ELEMENT_BEAM" || starts_with(name, "ELEMENT_BEAM_")) {
    section_ = Section::Beam;
    bool sizes = false;
    for (const std::string& o : options_of(name, "ELEMENT_BEAM")) {
      if (o == "THICKNESS" || o == "SCALAR" || o == "SCALR" || o == "SECTION")
        sizes = true;
      else if (o == "PID" || o == "OFFSET" || o == "ORIENTATION" || o == "WARPAGE")
        ++cards_each_;
      else
        section_ = Section::Other;
    }
    cards_each_ += sizes;
  } else if (name == "ELEMENT_TSHELL" || name == "ELEMENT_TSHELL_BETA") {
    section_ = Section::PinOnly;
    node_fields_ = {2, 3, 4, 5, 6, 7, 8, 9};
    cards_each_ += name != "ELEMENT_TSHELL";
  } else if (name == "ELEMENT_DISCRETE") {
    section_ = Section::PinOnly;
    node_fields_ = {2, 3};
  } else if (name == "ELEMENT_MASS") {
    section_ = Section::PinOnly;
    node_fields_ = {1};
  } else if (is_part_keyword(name)) {
    section_ = Section::Part;
    parts_all_ = name == "PART";
  } else if (name == "SET_NODE" || name == "SET_NODE_LIST" || name == "SET_NODE_TITLE" ||
             name == "SET_NODE_LIST_TITLE") {
    section_ = Section::NodeSet;
  } else if (name == "SET_NODE_LIST_GENERATE" || name == "SET_NODE_LIST_GENERATE_TITLE") {
    section_ = Section::NodeRanges;
  } else if (name == "SET_SEGMENT" || name == "SET_SEGMENT_TITLE") {
    section_ = Section::Segments;
  } else {
    for (const NodeFieldKeyword& known : node_field_keywords())
      if (name == known.name) {
        section_ = Section::NodeFields;
        node_fields_ = known.fields;
      }
  }
  if (section_ == Section::NodeSet || section_ == Section::NodeRanges || section_ == Section::Segments) {
    head_pending_ = true;
    title_pending_ = name.size() > 6 && name.compare(name.size() - 6, 6, "_TITLE") == 0;
  }
  if (section_ == Section::PinOnly) add_once(uncarried_, name);
  if (section_ == Section::Other && names_nodes(name)) add_once(unread_, name);
  // The keywords other formats do not write (elements that only pin among
  // them).
  if (section_ != Section::Node && section_ != Section::Solid && section_ != Section::Shell &&
      section_ != Section::Beam)
    add_once(keywords_, name);
}

void DeckReader::node(const std::string& line) {
  const Card card = card_of(line, node_widths(layout_));
  const long long id = id_field(card[0], "a node id (NID)");
  for (std::size_t c = 0; c < 3; ++c) {
    double v = 0;
    if (!real_field(card[1 + c], v))
      fail("node " + std::to_string(id) + ": expected a finite coordinate, found " + quoted_token(card[1 + c]));
    mesh_.xyz.push_back(v);
  }
  long long tc = 0, rc = 0;
  if (!int_field(card[4], tc) || !int_field(card[5], rc))
    fail("node " + std::to_string(id) + ": expected its constraints TC and RC as whole numbers, found " +
         quoted_token(card[int_field(card[4], tc) ? 5 : 4]));
  mesh_.extras.node_tags.push_back(id);
  node_marks_.push_back(lines_.mark());
  constrained_.push_back(tc != 0 || rc != 0);
}

void DeckReader::other_element(const std::string& kind, int nodes, long long id, int pid, const long long* n) {
  auto it = std::find_if(others_.begin(), others_.end(), [&](const Others& o) { return o.kind == kind; });
  if (it == others_.end()) it = others_.insert(others_.end(), Others{kind, nodes, {}, {}, {}, {}});
  it->ids.push_back(id);
  it->nodes_of.insert(it->nodes_of.end(), n, n + nodes);
  it->pids.push_back(pid);
  it->marks.push_back(lines_.mark());
}

void DeckReader::solid_nodes(const long long* n, int count) {
  // A blank node field reads as 0, which names no node: degenerate solids
  // repeat a node instead, and only a tet's N5-N8 may stay blank. A card
  // cut short (a deck copied in part) would otherwise lose its element.
  const auto blank = [&](int k) {
    fail("solid element " + std::to_string(pending_id_) + " leaves node N" + std::to_string(k + 1) +
         " blank or 0, which names no node (a card cut short?)");
  };
  const bool ten = count == 10 && (n[8] != 0 || n[9] != 0);  // a 10-node tet's second card: all ten given
  for (int k = 0; k < (ten ? 10 : 4); ++k)
    if (n[k] == 0) blank(k);
  if (!ten && !all_equal(n, 4, 8, 0))
    for (int k = 4; k < 8; ++k)
      if (n[k] == 0) blank(k);
  solid_ids_.push_back(pending_id_);
  solid_marks_.push_back(lines_.mark());
  const auto tet = [&](std::initializer_list<int> places) {
    const int each = static_cast<int>(places.size());
    if (tet_nodes_each_ != 0 && tet_nodes_each_ != each) fail(mixed_tet_kinds(each));
    tet_nodes_each_ = each;
    for (int p : places) tet_nodes_.push_back(n[p]);
    mesh_.extras.tet_element_tags.push_back(pending_id_);
    mesh_.extras.tet_tags.push_back(pending_pid_);
    tet_marks_.push_back(lines_.mark());
  };
  const auto passed = [&](const char* kind, std::initializer_list<int> places) {
    long long listed[8];
    int k = 0;
    for (int p : places) listed[k++] = n[p];
    other_element(kind, k, pending_id_, pending_pid_, listed);
  };
  // A second card of ten nodes: a 10-node tet, or eight nodes as on one card.
  if (count == 10 && (n[8] != 0 || n[9] != 0)) {
    if (distinct(n, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9})) return tet({0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
  } else if (distinct(n, {0, 1, 2, 3}) && (all_equal(n, 4, 8, n[3]) || all_equal(n, 4, 8, 0))) {
    return tet({0, 1, 2, 3});
  } else if (n[2] == n[3] && all_equal(n, 5, 8, n[4]) && distinct(n, {0, 1, 2, 4})) {
    return tet({0, 1, 2, 4});
  } else if (distinct(n, {0, 1, 2, 3, 4, 5, 6, 7})) {
    return passed("hexahedron", {0, 1, 2, 3, 4, 5, 6, 7});
  } else if (n[4] == n[5] && n[6] == n[7] && distinct(n, {0, 1, 2, 3, 4, 6})) {
    // Two triangles (N1, N2, N5) and (N4, N3, N6): the first turned round,
    // so that it faces the second, as a wedge's first triangle does.
    return passed("wedge", {0, 4, 1, 3, 6, 2});
  } else if (all_equal(n, 5, 8, n[4]) && distinct(n, {0, 1, 2, 3, 4})) {
    return passed("pyramid", {0, 1, 2, 3, 4});
  }
  // Any other solid only pins its nodes.
  add_once(uncarried_, "ELEMENT_SOLID (" + std::to_string(count) + "-node)");
  for (int k = 0; k < count; ++k)
    if (n[k] > 0) pin_refs_.push_back(PinRef{n[k], n[k], keyword_, lines_.mark()});
}

void DeckReader::solid(const Card& card) {
  long long n[10] = {};
  if (card_ == 0) {
    pending_id_ = id_field(card[0], "an element id (EID)");
    pending_pid_ = pid_field(card[1]);
    bool nodes_given = false;
    for (std::size_t k = 2; k < 10; ++k) nodes_given = nodes_given || !card[k].empty();
    if (nodes_given) {
      for (std::size_t k = 0; k < 8; ++k) n[k] = id_field(card[2 + k], "a node id", true);
      solid_nodes(n, 8);
      card_ = cards_each_ > 1 ? 1 : 0;
    } else {
      card_ = 1;  // its nodes on the next card
      two_card_ = true;
    }
    return;
  }
  if (two_card_ && card_ == 1) {
    for (std::size_t k = 0; k < 10; ++k) n[k] = id_field(card[k], "a node id", true);
    solid_nodes(n, 10);
  }
  if (++card_ == cards_each_ + (two_card_ ? 1 : 0)) {
    card_ = 0;
    two_card_ = false;
  }
}

void DeckReader::shell(const Card& card) {
  if (card_ == 0) {
    const long long id = id_field(card[0], "an element id (EID)");
    const int pid = pid_field(card[1]);
    long long n[8];
    for (std::size_t k = 0; k < 8; ++k) n[k] = id_field(card[2 + k], "a node id", true);
    if (all_equal(n, 4, 8, 0) && (n[3] == n[2] || n[3] == 0) && distinct(n, {0, 1, 2})) {
      other_element("triangle", 3, id, pid, n);
    } else if (all_equal(n, 4, 8, 0) && distinct(n, {0, 1, 2, 3})) {
      other_element("quad", 4, id, pid, n);
    } else {
      add_once(uncarried_, "ELEMENT_SHELL (other than triangles and quads)");
      for (long long v : n)
        if (v > 0) pin_refs_.push_back(PinRef{v, v, keyword_, lines_.mark()});
    }
  }
  if (++card_ == cards_each_) card_ = 0;
}

void DeckReader::beam(const Card& card) {
  if (card_ == 0) {
    const long long id = id_field(card[0], "an element id (EID)");
    const int pid = pid_field(card[1]);
    const long long n[3] = {id_field(card[2], "a node id"), id_field(card[3], "a node id"),
                            id_field(card[4], "an orientation node id", true)};
    if (n[0] != n[1])
      other_element("line", 2, id, pid, n);
    else
      pin_refs_.push_back(PinRef{n[0], n[0], keyword_, lines_.mark()});
    if (n[2] > 0) pin_refs_.push_back(PinRef{n[2], n[2], keyword_, lines_.mark()});
  }
  if (++card_ == cards_each_) card_ = 0;
}

void DeckReader::pin_fields(const Card& card, const std::vector<int>& fields) {
  for (const int f : fields)
    if (const long long id = id_field(card[static_cast<std::size_t>(f)], "a node id", true); id > 0)
      pin_refs_.push_back(PinRef{id, id, keyword_, lines_.mark()});
}

void DeckReader::part(const std::string& line) {
  if (part_pid_card_ == 0) {
    part_heading_ = std::string(trimmed(line));
    part_pid_card_ = 1;
    return;
  }
  if (part_pid_card_ == 1) {
    const Card card = card_of(line, wide_widths(layout_));
    const int pid = pid_field(card[0]);
    if (!part_heading_.empty()) part_names_.emplace_back(pid, part_heading_);
  }
  // A plain *PART goes on with the next part's heading; options add cards
  // of their own, which are not followed.
  part_pid_card_ = parts_all_ ? 0 : 2;
}

void DeckReader::node_list(const Card& card, bool ranges) {
  for (std::size_t k = 0; k < (ranges ? 8u : card.fields.size()); k += ranges ? 2 : 1) {
    const long long first = id_field(card[k], "a node id", true);
    if (!ranges) {
      if (first > 0) pin_refs_.push_back(PinRef{first, first, keyword_, lines_.mark()});
      continue;
    }
    const long long last = id_field(card[k + 1], "the last node id of a range", true);
    if (first == 0 && last == 0) continue;
    if (first == 0 || last < first)
      fail("*" + keyword_ + ": the range " + std::to_string(first) + " to " + std::to_string(last) +
           " is no range of node ids");
    pin_refs_.push_back(PinRef{first, last, keyword_, lines_.mark()});
  }
}

std::string DeckReader::written_inline(const std::string& line) const {
  // The deck's layout holds where an included file's text goes: the file's
  // *KEYWORD becomes a comment, and its keywords are marked with its layout
  // where that differs.
  const Keyword k = keyword_of(line);
  if (k.name == "KEYWORD" || k.name == "KEYWORD_ID") return "$" + line;
  if (k.marked || layout_ == outer_layouts_.front().deck) return line;
  const std::size_t name_end = std::min(line.find_first_of(" \t\r"), line.size());
  return line.substr(0, name_end) + " " + layout_mark(layout_) + line.substr(name_end);
}

void DeckReader::include(const std::string& line) {
  // A name ending in " +" goes on on the next card.
  const std::string_view text = trimmed(line);
  if (text.size() >= 2 && text.substr(text.size() - 2) == " +") {
    include_name_ += std::string(trimmed(text.substr(0, text.size() - 2)));
    return;
  }
  const std::string name = include_name_ + std::string(text);
  include_name_.clear();
  lines_.include(name, "*INCLUDE", lines_.mark());
}

void DeckReader::data(const std::string& line) {
  const bool blank = trimmed(line).empty();
  switch (section_) {
    case Section::Other:
    case Section::Ended:
      break;
    case Section::Include:
      if (!blank) return include(line);  // the file comes in its place
      break;
    case Section::Node:
      if (!blank) node(line);
      return keep(line, true);
    // A blank line is a card of defaults (an option's card left blank), but
    // where an element's first card would come, where it is skipped.
    case Section::Solid:
      if (!blank || card_ != 0) solid(card_of(line, element_widths(layout_)));
      break;
    case Section::Shell:
      if (!blank || card_ != 0) shell(card_of(line, element_widths(layout_)));
      break;
    case Section::Beam:
      if (!blank || card_ != 0) beam(card_of(line, element_widths(layout_)));
      break;
    case Section::PinOnly:
      if (blank && card_ == 0) break;
      if (card_ == 0) pin_fields(card_of(line, element_widths(layout_)), node_fields_);
      if (++card_ == cards_each_) card_ = 0;
      break;
    case Section::Part:
      part(line);  // a blank heading is a heading
      break;
    case Section::NodeSet:
    case Section::NodeRanges:
    case Section::Segments:
      if (blank && !title_pending_ && !head_pending_) break;  // a title or an id card may be blank
      if (title_pending_) {
        title_pending_ = false;
      } else if (head_pending_) {
        head_pending_ = false;
      } else if (section_ == Section::Segments) {
        const Card card = card_of(line, wide_widths(layout_));
        node_list(Card{{card[0], card[1], card[2], card[3]}, card.free}, false);
      } else {
        node_list(card_of(line, wide_widths(layout_)), section_ == Section::NodeRanges);
      }
      break;
    case Section::NodeFields:
      if (!blank) pin_fields(card_of(line, wide_widths(layout_)), node_fields_);
      break;
  }
  keep(inline_comments_ ? "$" + line : line, false);
}

void DeckReader::keep_notes() {
  FileExtras& e = mesh_.extras;
  stamp_kept_deck(mesh_, "lsdyna");
  if (!keywords_.empty()) e.raw_sections.emplace_back("lsdyna:keywords", joined(keywords_));
  if (!uncarried_.empty()) e.raw_sections.emplace_back("lsdyna:uncarried", joined(uncarried_));
  if (!lines_.included().empty()) e.raw_sections.emplace_back("lsdyna:includes", joined(lines_.included()));
  if (!unread_.empty())
    e.read_notes.push_back("the deck's " + joined(unread_) +
                           " keywords are not read: where they name nodes, those nodes are not pinned (list the "
                           "nodes that must stay in a *SET_NODE_LIST)");
  // LS-DYNA reads to the end of the file without *END, but the writers put
  // it there: a deck that opens with *KEYWORD and lacks it may be cut short.
  if (deck_keyword_ && !deck_end_)
    e.read_notes.push_back(
        "the deck has *KEYWORD but ends without *END, as a deck cut short would: check that its "
        "last cards are all there");
}

TetMesh DeckReader::read() {
  std::string line;
  std::size_t depth = 1;
  while (lines_.next(line)) {
    // An included file's layout is its *INCLUDE's; back in the file that
    // named it, that file's own layouts hold again.
    if (lines_.depth() > depth) {
      outer_layouts_.push_back({deck_layout_, include_layout_});
      deck_layout_ = include_layout_;
    }
    for (; outer_layouts_.size() >= lines_.depth(); outer_layouts_.pop_back()) {
      deck_layout_ = outer_layouts_.back().deck;
      include_layout_ = outer_layouts_.back().include;
    }
    // Back from an included file: the cards that follow name more files.
    if (lines_.depth() < depth) {
      if (card_ != 0 && section_ != Section::Other && section_ != Section::Ended)
        fail("*" + keyword_ + ": the included file ends inside an element's cards");
      section_ = Section::Include;
      keyword_ = "INCLUDE";
      include_name_.clear();
      inline_comments_ = false;
    }
    depth = lines_.depth();
    // An included file's *END ends that file alone: it and what follows are
    // left out of the deck, which writes the file inline.
    if (section_ == Section::Ended) {
      if (depth == 1) keep(line, false);
    } else if (!line.empty() && line[0] == '*') {
      keyword(line);
      if (section_ != Section::Include && (section_ != Section::Ended || depth == 1))
        keep(depth == 1 ? line : written_inline(line), false);
    } else if (!line.empty() && line[0] == '$') {
      keep(line, section_ == Section::Node);
    } else {
      data(line);
    }
  }
  if (card_ != 0 && section_ != Section::Other && section_ != Section::Ended)
    fail("*" + keyword_ + ": the deck ends inside an element's cards");
  flush_kept();
  if (mesh_.num_nodes() == 0) throw InputError(source_, "no *NODE cards: not an LS-DYNA mesh");
  if (tet_marks_.empty()) throw InputError(source_, "no tets in *ELEMENT_SOLID: a volume mesh of tets is needed");
  resolve();
  keep_notes();
  validate_mesh(mesh_, source_);
  return std::move(mesh_);
}

}  // namespace lsdyna

TetMesh read_lsdyna(std::istream& in, const std::string& source) { return lsdyna::DeckReader(in, source).read(); }

TetMesh read_lsdyna_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_lsdyna(in, path);
}

}  // namespace tetsmooth
