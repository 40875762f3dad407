#include "domain/dxf_groups.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "common/numbers.hpp"
#include "frontpack/errors.hpp"

namespace frontpack::detail {

namespace {

using Kind = DomainFileError::Kind;

// dxflib reads a line into a buffer of 1024 bytes with fgets: a longer line would reach it as two.
constexpr std::size_t kMaxLine = 1022;
constexpr int kMaxCode = 1071;

[[noreturn]] void fail(Kind kind, const std::string& detail, const std::string& source) {
  throw DomainFileError(kind, detail, source);
}

std::string at_line(std::size_t line) {
  return "line " + std::to_string(line);
}

// The file's lines, split at "\n" (a "\r" before it, and blanks at both ends, removed as dxflib
// removes them), with the number of lines the text holds.
class Lines {
 public:
  // A UTF-8 byte order mark before the first group is skipped (dxflib's strtol read past it).
  Lines(std::string_view text, const std::string& source)
      : text_(text.substr(text.starts_with("\xEF\xBB\xBF") ? 3 : 0)), source_(source) {}

  // The next line, or false at the end of the text.
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) {
      return false;
    }
    const std::size_t end = text_.find('\n', pos_);
    std::string_view raw = text_.substr(pos_, end == std::string_view::npos ? std::string_view::npos : end - pos_);
    pos_ = end == std::string_view::npos ? text_.size() : end + 1;
    ++number_;
    if (raw.size() > kMaxLine) {
      fail(Kind::bad_structure,
           at_line(number_) + " has " + std::to_string(raw.size()) + " characters; a DXF line has at most " +
               std::to_string(kMaxLine),
           source_);
    }
    if (raw.find('\0') != std::string_view::npos) {
      fail(Kind::bad_structure, at_line(number_) + " holds a NUL byte", source_);
    }
    while (!raw.empty() && (raw.back() == '\r' || raw.back() == ' ' || raw.back() == '\t')) {
      raw.remove_suffix(1);
    }
    while (!raw.empty() && (raw.front() == ' ' || raw.front() == '\t')) {
      raw.remove_prefix(1);
    }
    line = raw;
    return true;
  }
  [[nodiscard]] std::size_t number() const { return number_; }

 private:
  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
};

bool is_name(std::string_view v) {
  bool letter = false;
  for (const char c : v) {
    const bool alpha = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    if (!alpha && !(c >= '0' && c <= '9') && c != '_') {
      return false;
    }
    letter = letter || alpha;
  }
  return letter;
}

[[noreturn]] void cut_short(std::size_t last_line, const std::string& where, const std::string& source) {
  fail(Kind::truncated,
       "the file ends before EOF, at " + at_line(last_line) + where +
           ": it was cut short (a DXF file ends with the groups '0' and 'EOF')",
       source);
}

[[noreturn]] void bad_number(const DxfGroup& g, const std::string& what, const std::string& source,
                             const std::string& entity) {
  throw DomainFileError(Kind::bad_number, "group " + std::to_string(g.code) + " (" + at_line(g.line) + "): " + what,
                        source, entity);
}

}  // namespace

std::vector<DxfGroup> read_dxf_groups(std::string_view text, const std::string& source) {
  Lines lines(text, source);
  std::vector<DxfGroup> groups;
  std::string section;  // the open section's name, empty between sections
  std::size_t section_line = 0;
  std::string_view code_text;
  while (lines.next(code_text)) {
    const std::size_t code_line = lines.number();
    int code = -1;
    const auto [end, ec] = std::from_chars(code_text.data(), code_text.data() + code_text.size(), code);
    if (code_text.empty() || ec != std::errc{} || end != code_text.data() + code_text.size() || code < 0 ||
        code > kMaxCode) {
      fail(Kind::bad_structure,
           at_line(code_line) + ": " + quote_text(code_text) + " is not a group code (a whole number from 0 to " +
               std::to_string(kMaxCode) + "); a value line may be missing before it",
           source);
    }
    std::string_view value;
    if (!lines.next(value)) {
      cut_short(code_line, " (group code " + std::to_string(code) + " without its value)", source);
    }
    const DxfGroup g{code, value, lines.number()};
    // A group 0 starts an entity, a table entry, an object or a section: its value is a name
    // (LINE, 3DFACE, ACDBDICTIONARYWDFLT). A number there is a value line lost before it.
    if (code == 0 && !is_name(value)) {
      fail(Kind::bad_structure,
           at_line(g.line) + ": group 0 " + quote_text(value) +
               " is not a name (of an entity, table or section); a value line may be missing before it",
           source);
    }
    groups.push_back(g);
    if (code == 999) {
      continue;  // a comment, anywhere
    }
    if (section.empty()) {
      // Between sections: SECTION and its name, or EOF.
      if (code == 0 && value == "EOF") {
        return groups;
      }
      if (code != 0 || value != "SECTION") {
        fail(Kind::bad_structure,
             at_line(g.line) + ": group " + std::to_string(code) + " " + quote_text(value) +
                 " between sections; expected SECTION or EOF",
             source);
      }
      std::string_view name_code;
      std::string_view name;
      if (!lines.next(name_code) || !lines.next(name)) {
        cut_short(lines.number(), " (a SECTION without its name)", source);
      }
      if (name_code != "2" || name.empty()) {
        fail(Kind::bad_structure,
             at_line(lines.number()) + ": SECTION (" + at_line(g.line) + ") must be followed by group 2, its name",
             source);
      }
      groups.push_back({2, name, lines.number()});
      section = std::string(name);
      section_line = lines.number();
    } else if (code == 0 && value == "ENDSEC") {
      section.clear();
    } else if (code == 0 && (value == "SECTION" || value == "EOF")) {
      fail(Kind::bad_structure,
           "section " + quote_text(section) + " (" + at_line(section_line) + ") has no ENDSEC before the " +
               std::string(value) + " at " + at_line(g.line),
           source);
    }
  }
  cut_short(lines.number(), section.empty() ? std::string() : " (inside section " + quote_text(section) + ")", source);
}

DxfValueType dxf_value_type(int code) noexcept {
  const auto in = [code](int a, int b) { return code >= a && code <= b; };
  if (in(10, 59) || in(110, 149) || in(210, 239) || in(460, 469) || in(1010, 1059)) {
    return DxfValueType::real;
  }
  if (in(60, 79) || in(90, 99) || in(160, 179) || in(270, 299) || in(370, 389) || in(400, 409) || in(420, 429) ||
      in(440, 459) || in(1060, 1071)) {
    return DxfValueType::integer;
  }
  return DxfValueType::text;
}

double dxf_real(const DxfGroup& g, const std::string& source, const std::string& entity) {
  if (g.value.empty()) {
    bad_number(g, "expected a number, got nothing", source, entity);
  }
  const Decimal d = parse_decimal(g.value);
  if (d.status == DecimalStatus::overflow || d.status == DecimalStatus::underflow) {
    bad_number(g, out_of_range(g.value, d.status), source, entity);
  }
  if (d.status != DecimalStatus::ok) {
    bad_number(g, quote_text(g.value) + " is not a number", source, entity);
  }
  if (!std::isfinite(d.value)) {
    bad_number(g, quote_text(g.value) + " is not a finite number", source, entity);
  }
  return d.value;
}

long long dxf_integer(const DxfGroup& g, long long min, long long max, const std::string& source,
                      const std::string& entity) {
  if (g.value.empty()) {
    bad_number(g, "expected a whole number, got nothing", source, entity);
  }
  long long v = 0;
  const auto [end, ec] = std::from_chars(g.value.data(), g.value.data() + g.value.size(), v);
  if (ec != std::errc{} || end != g.value.data() + g.value.size() || v < min || v > max) {
    bad_number(
        g, quote_text(g.value) + " is not a whole number from " + std::to_string(min) + " to " + std::to_string(max),
        source, entity);
  }
  return v;
}

void check_dxf_number(const DxfGroup& g, const std::string& source, const std::string& entity) {
  const auto in = [&g](int a, int b) { return g.code >= a && g.code <= b; };
  switch (dxf_value_type(g.code)) {
    case DxfValueType::real: (void)dxf_real(g, source, entity); break;
    case DxfValueType::integer:
      // 16-bit codes, 32-bit ones (90-99, 420-459, 1071), 64-bit ones (160-169), as the reference types them.
      if (in(160, 169)) {
        (void)dxf_integer(g, std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max(), source,
                          entity);
      } else if (in(90, 99) || in(420, 459) || g.code == 1071) {
        (void)dxf_integer(g, std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max(), source,
                          entity);
      } else {
        (void)dxf_integer(g, std::numeric_limits<std::int16_t>::min(), std::numeric_limits<std::int16_t>::max(), source,
                          entity);
      }
      break;
    case DxfValueType::text: break;
  }
}

std::string dxf_entity_name(std::string_view type, std::string_view handle, std::size_t line) {
  const auto plain = [](std::string_view text) {
    const bool word =
        !text.empty() && text.size() <= kQuotedChars &&
        text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_") == std::string::npos;
    return word ? std::string(text) : quote_text(text);
  };
  return plain(type) + " (" + (handle.empty() ? std::string() : "handle " + plain(handle) + ", ") + at_line(line) + ")";
}

void check_dxf_counts(const std::vector<DxfGroup>& groups, const std::string& source) {
  for (std::size_t start = 0; start < groups.size();) {
    std::size_t end = start + 1;
    while (end < groups.size() && groups[end].code != 0) {
      ++end;
    }
    const std::string_view type = groups[start].value;
    if (groups[start].code == 0 && (type == "LWPOLYLINE" || type == "SPLINE" || type == "LEADER")) {
      std::string_view handle;
      long long vertices = 0;
      for (std::size_t i = start + 1; i < end; ++i) {
        handle = groups[i].code == 5 ? groups[i].value : handle;
        vertices += groups[i].code == 10 ? 1 : 0;
      }
      const std::string name = dxf_entity_name(type, handle, groups[start].line);
      const auto groups_in = static_cast<long long>(end - start);
      bool counted = false;
      for (std::size_t i = start + 1; i < end; ++i) {
        const DxfGroup& g = groups[i];
        const bool count = type == "LWPOLYLINE" ? g.code == 90
                           : type == "SPLINE"   ? (g.code >= 72 && g.code <= 74)
                                                : g.code == 76;
        if (!count) {
          continue;
        }
        counted = true;
        const long long n = dxf_integer(g, 0, groups_in, source, name);
        if (type == "LWPOLYLINE" && n != vertices) {
          bad_number(
              g, quote_text(g.value) + " vertices, but the LWPOLYLINE has " + std::to_string(vertices) + " (groups 10)",
              source, name);
        }
      }
      // dxflib keeps the previous LWPOLYLINE's count (and vertices) for one without its own.
      if (type == "LWPOLYLINE" && !counted) {
        throw DomainFileError(Kind::bad_structure, "no group 90 (its number of vertices)", source, name);
      }
    }
    start = end;
  }
}

const char* dxf_units_name(long long code) noexcept {
  static constexpr const char* kNames[] = {"unitless",
                                           "inches",
                                           "feet",
                                           "miles",
                                           "millimeters",
                                           "centimeters",
                                           "meters",
                                           "kilometers",
                                           "microinches",
                                           "mils",
                                           "yards",
                                           "angstroms",
                                           "nanometers",
                                           "microns",
                                           "decimeters",
                                           "decameters",
                                           "hectometers",
                                           "gigameters",
                                           "astronomical units",
                                           "light years",
                                           "parsecs",
                                           "US survey feet",
                                           "US survey inches",
                                           "US survey yards",
                                           "US survey miles"};
  return code >= 0 && code <= kDxfUnitsMax ? kNames[code] : "";
}

}  // namespace frontpack::detail
