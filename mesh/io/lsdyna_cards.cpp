// LS-DYNA keyword lines and card fields (lsdyna_cards.hpp).
#include "mesh/io/lsdyna_cards.hpp"

#include <cmath>

#include "mesh/io/nastran_fields.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth::lsdyna {

const std::string_view Card::kBlank{};

const std::string_view& Card::operator[](std::size_t k) const { return k < fields.size() ? fields[k] : kBlank; }

Keyword keyword_of(std::string_view line) {
  Keyword k;
  line.remove_prefix(1);
  std::size_t end = 0;
  while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != '\r') ++end;
  std::string_view name = line.substr(0, end);
  std::string_view rest = trimmed(line.substr(end));
  const auto mark = [&](char c) {
    k.marked = true;
    k.layout = c == '+' ? Layout::Long : c == '%' ? Layout::I10 : Layout::Standard;
  };
  // The mark ends the name ("*NODE%") or comes after it ("*NODE %").
  if (!name.empty() && (name.back() == '+' || name.back() == '%' || name.back() == '-')) {
    mark(name.back());
    name.remove_suffix(1);
  } else if (!rest.empty() && (rest[0] == '+' || rest[0] == '%' || rest[0] == '-') &&
             (rest.size() == 1 || rest[1] == ' ' || rest[1] == '\t')) {
    mark(rest[0]);
    rest = trimmed(rest.substr(1));
  }
  k.name = upper_case(name);
  k.rest = std::string(rest);
  return k;
}

Card card_of(std::string_view line, const std::vector<int>& widths) {
  Card card;
  if (line.find(',') != std::string_view::npos) {
    card.free = true;
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = line.find(',', start);
      card.fields.push_back(trimmed(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    return card;
  }
  std::size_t at = 0;
  for (const int w : widths) {
    if (at >= line.size()) break;
    card.fields.push_back(trimmed(line.substr(at, static_cast<std::size_t>(w))));
    at += static_cast<std::size_t>(w);
  }
  return card;
}

bool int_field(std::string_view field, long long& value) {
  field = trimmed(field);
  if (field.empty()) {
    value = 0;
    return true;
  }
  if (parse_integer(field, value)) return true;
  // Cards LS-DYNA reads as reals ("F8.0": TC and RC) may hold whole numbers
  // written as reals.
  double v = 0;
  if (!nastran::parse_real_field(field, v) || v != std::floor(v) || std::fabs(v) > 9.0e15) return false;
  value = static_cast<long long>(v);
  return true;
}

bool real_field(std::string_view field, double& value) {
  field = trimmed(field);
  if (field.empty()) {
    value = 0;
    return true;
  }
  return nastran::parse_real_field(field, value);
}

const char* layout_mark(Layout layout) { return layout == Layout::Long ? "+" : layout == Layout::I10 ? "%" : "-"; }

const char* layout_name(Layout layout) {
  return layout == Layout::Long ? "long" : layout == Layout::I10 ? "I10" : "standard";
}

std::string coordinate_field(double value, std::size_t width) {
  // Fortran reads ".5" and "1.5E2", but readers written in C may not
  // (lsdyna-mesh-reader reads neither): C's style. One character fewer
  // than the field leaves a blank before it.
  std::string field = nastran::real_field(value, width - 1, nastran::RealStyle::C);
  field.insert(0, width - field.size(), ' ');
  return field;
}

std::string free_coordinate(double value, std::size_t width) {
  return std::string(trimmed(coordinate_field(value, width)));
}

const std::vector<int>& node_widths(Layout layout) {
  static const std::vector<int> standard{8, 16, 16, 16, 8, 8}, i10{10, 16, 16, 16, 10, 10}, wide(6, 20);
  return layout == Layout::Long ? wide : layout == Layout::I10 ? i10 : standard;
}

const std::vector<int>& element_widths(Layout layout) {
  static const std::vector<int> standard(10, 8), i10(10, 10), wide(10, 20);
  return layout == Layout::Long ? wide : layout == Layout::I10 ? i10 : standard;
}

const std::vector<int>& wide_widths(Layout layout) {
  static const std::vector<int> widths(8, 10), wide(8, 20);
  return layout == Layout::Long ? wide : widths;
}

}  // namespace tetsmooth::lsdyna
