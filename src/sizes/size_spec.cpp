// The radius spec syntax (parse_radii) and the CSV size tables (read_size_table); the grammar
// is documented in include/frontpack/sizes.hpp and docs/distributions.md.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "common/format.hpp"
#include "common/numbers.hpp"
#include "common/read_file.hpp"
#include "common/text.hpp"
#include "frontpack/errors.hpp"
#include "frontpack/sizes.hpp"

namespace frontpack {

namespace {

using detail::format_double;

constexpr const char* kExpected =
    "expected uniform:RMIN,RMAX or constant:R or normal:MEAN,SD[,LO,HI] or lognormal:MEDIAN,GSD[,LO,HI] or "
    "discrete:S:F,...[@area] or discrete:FILE.csv or curve:D:P,...[@number] or curve:FILE.csv";

using detail::split;

std::string_view trim(std::string_view s) {
  return detail::trim(s, detail::is_c_space);
}

// A whole field (trimmed, a leading '+' allowed) as a double: C locale, "nan" and "inf" included
// (the callers check finiteness with a message that says what the number is), and out of the
// range of doubles refused as by every reader (common/numbers.hpp): the status says which.
detail::Decimal to_double(std::string_view text) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && (text.front() == '-' || text.front() == '+')) {
      return {};  // "+-1": one sign at most (malformed)
    }
  }
  return detail::parse_decimal(text);
}

bool out_of_range(const detail::Decimal& d) {
  return d.status == detail::DecimalStatus::overflow || d.status == detail::DecimalStatus::underflow;
}

// What is wrong with field `text` that to_double() read as `d` (not ok): "'1e-400' is out of the
// range of a double (underflows to 0)" or "'x' is not a number".
std::string number_problem(std::string_view text, const detail::Decimal& d) {
  text = trim(text);
  return out_of_range(d) ? detail::out_of_range(text, d.status) : detail::quote_text(text) + " is not a number";
}

// 'text', quoted and escaped, at most 40 characters of it (common/numbers.hpp); a whole spec or a file
// name up to 160.
std::string in_quotes(std::string_view text, std::size_t max_chars = detail::kQuotedChars) {
  return detail::quote_text(text, max_chars);
}
constexpr std::size_t kWholeSpec = 160;

bool ends_with_csv(std::string_view s) {
  return s.size() >= 4 && detail::ascii_lower(s.substr(s.size() - 4)) == ".csv";
}

class SpecParser {
 public:
  explicit SpecParser(std::string_view spec) : spec_(spec) {}

  Radii parse() {
    const std::size_t colon = spec_.find(':');
    if (colon == std::string_view::npos) {
      fail(std::string(kExpected));
    }
    const std::string_view kind = trim(spec_.substr(0, colon));
    std::string_view args = spec_.substr(colon + 1);
    const std::size_t at = args.find('@');
    if (at != std::string_view::npos) {
      read_modifiers(args.substr(at + 1));
      args = args.substr(0, at);
    }
    try {
      if (kind == "uniform" || kind == "constant" || kind == "normal" || kind == "lognormal") {
        if (modified_) {
          fail("@ modifiers apply to discrete: and curve: only");
        }
        return parametric(kind, args);
      }
      if (kind == "discrete" || kind == "curve") {
        return table(kind == "curve", args);
      }
    } catch (const OptionError& e) {
      // The factories' messages start "radius: "; name the spec instead.
      std::string_view message = e.what();
      if (message.starts_with("radius: ")) {
        message.remove_prefix(8);
      }
      if (message.starts_with(prefix())) {
        throw;
      }
      fail(std::string(message));
    }
    fail("unknown distribution " + in_quotes(kind) + "; " + kExpected);
  }

 private:
  [[nodiscard]] std::string prefix() const { return "radius " + in_quotes(spec_, kWholeSpec) + ": "; }
  [[noreturn]] void fail(const std::string& detail) const { throw OptionError(prefix() + detail); }

  void read_modifiers(std::string_view text) {
    modified_ = true;
    for (const std::string_view raw : split(text, '@')) {
      const std::string_view word = trim(raw);
      std::string modifier("@");  // (appended: GCC 12 warns falsely, -Wrestrict, about "@" + string)
      modifier += word;
      bool* seen = nullptr;
      if (word == "area" || word == "number") {
        seen = &basis_given_;
        basis_ = word == "area" ? Basis::area : Basis::number;
      } else if (word == "radius" || word == "diameter") {
        seen = &kind_given_;
        kind_ = word == "radius" ? SizeKind::radius : SizeKind::diameter;
      } else {
        fail("unknown modifier " + in_quotes(modifier) + "; expected @area, @number, @radius or @diameter");
      }
      if (*seen) {
        fail("modifier " + in_quotes(modifier) + " conflicts with or repeats an earlier one");
      }
      *seen = true;
    }
  }

  // The numbers of `args`, and in `tokens` the text of each as given (trimmed), for messages.
  std::vector<double> numbers(std::string_view kind, std::string_view args, std::size_t min_count,
                              std::size_t max_count, const char* syntax,
                              std::vector<std::string_view>* tokens = nullptr) const {
    std::vector<double> values;
    const std::vector<std::string_view> fields = split(args, ',');
    if (fields.size() < min_count || fields.size() > max_count) {
      fail(std::string(kind) + " takes " + syntax + ", got " + std::to_string(fields.size()) + " value" +
           (fields.size() == 1 ? "" : "s"));
    }
    for (const std::string_view f : fields) {
      const detail::Decimal d = to_double(f);
      if (out_of_range(d)) {
        fail(number_problem(f, d));
      }
      if (d.status != detail::DecimalStatus::ok) {
        fail(number_problem(f, d) + " (" + std::string(kind) + ":" + syntax + ")");
      }
      values.push_back(d.value);
      if (tokens != nullptr) {
        tokens->push_back(trim(f));
      }
    }
    return values;
  }

  Radii parametric(std::string_view kind, std::string_view args) const {
    if (kind == "uniform") {
      const auto v = numbers(kind, args, 2, 2, "RMIN,RMAX");
      return Radii::uniform(v[0], v[1]);
    }
    if (kind == "constant") {
      return Radii::constant(numbers(kind, args, 1, 1, "R")[0]);
    }
    if (kind == "normal") {
      std::vector<std::string_view> t;
      auto v = numbers(kind, args, 2, 4, "MEAN,SD[,LO,HI]", &t);
      if (v.size() == 3) {
        fail("normal takes MEAN,SD or MEAN,SD,LO,HI, got 3 values");
      }
      if (v.size() == 2) {
        v.push_back(v[0] - 3 * v[1]);
        v.push_back(v[0] + 3 * v[1]);
        // Bounds the user did not give are named by the numbers given (MEAN and SD): a message
        // about a bound of "-inf" or "0.05" alone would name neither.
        if (std::isfinite(v[0]) && std::isfinite(v[1]) && v[1] > 0) {
          const std::string given = " (MEAN " + in_quotes(t[0]) + ", SD " + in_quotes(t[1]) + ")";
          const char* const hint = "; give the bounds: normal:MEAN,SD,LO,HI";
          if (!(v[2] > 0)) {
            fail("normal: the default lower bound MEAN - 3 SD = " + format_double(v[2]) + given + " is not > 0" + hint);
          }
          if (!std::isfinite(v[3])) {
            fail("normal: the default upper bound MEAN + 3 SD" + given + " overflows to infinity" + hint);
          }
          if (!(v[2] < v[3])) {
            fail("normal: the default bounds MEAN -/+ 3 SD" + given + " round to the same number, " +
                 format_double(v[2]) + ": SD is below the precision of MEAN" + hint);
          }
        }
      }
      return Radii::normal(v[0], v[1], v[2], v[3]);
    }
    std::vector<std::string_view> t;
    auto v = numbers(kind, args, 2, 4, "MEDIAN,GSD[,LO,HI]", &t);
    if (v.size() == 3) {
      fail("lognormal takes MEDIAN,GSD or MEDIAN,GSD,LO,HI, got 3 values");
    }
    if (v.size() == 2) {
      const double spread = v[1] * v[1] * v[1];
      v.push_back(v[0] / spread);
      v.push_back(v[0] * spread);
      // As for normal: default bounds out of range are named by MEDIAN and GSD.
      if (std::isfinite(v[0]) && v[0] > 0 && std::isfinite(v[1]) && v[1] > 1) {
        const std::string given = " (MEDIAN " + in_quotes(t[0]) + ", GSD " + in_quotes(t[1]) + ")";
        const char* const hint = "; give the bounds: lognormal:MEDIAN,GSD,LO,HI";
        if (!(v[2] > 0)) {
          fail("lognormal: the default lower bound MEDIAN / GSD^3" + given + " underflows to 0" + hint);
        }
        if (!std::isfinite(v[3])) {
          fail("lognormal: the default upper bound MEDIAN * GSD^3" + given + " overflows to infinity" + hint);
        }
      }
    }
    return Radii::lognormal(v[0], v[1], v[2], v[3]);
  }

  Radii table(bool curve, std::string_view args) const {
    const Basis basis = basis_given_ ? basis_ : (curve ? Basis::area : Basis::number);
    args = trim(args);
    if (ends_with_csv(args)) {
      if (kind_given_) {
        fail("@radius and @diameter apply to inline lists; the file's header says which");
      }
      const SizeTable t = read_size_table(std::filesystem::path(std::string(args)));
      if (t.cumulative != curve) {
        fail(in_quotes(args, kWholeSpec) + " has a '" + (t.cumulative ? "passing" : "fraction") + "' column (" +
             (t.cumulative ? "a grading curve): use curve:" : "discrete classes): use discrete:") + std::string(args));
      }
      return radii_from_table(t, basis);
    }
    std::vector<SizeFraction> rows;
    const std::vector<std::string_view> items = split(args, ',');
    for (std::size_t k = 0; k < items.size(); ++k) {
      const std::vector<std::string_view> pair = split(items[k], ':');
      const std::string item = std::string(curve ? "curve" : "discrete") + ": item " + std::to_string(k + 1);
      for (const std::string_view field : pair) {
        if (const detail::Decimal d = to_double(field); pair.size() == 2 && out_of_range(d)) {
          fail(item + ": " + number_problem(field, d));
        }
      }
      const detail::Decimal size = pair.size() == 2 ? to_double(pair[0]) : detail::Decimal{};
      const detail::Decimal fraction = pair.size() == 2 ? to_double(pair[1]) : detail::Decimal{};
      if (size.status != detail::DecimalStatus::ok || fraction.status != detail::DecimalStatus::ok) {
        fail(item + " " + in_quotes(trim(items[k])) + " is not " + (curve ? "SIZE:PASSING" : "SIZE:FRACTION") +
             " (two numbers)");
      }
      rows.push_back(SizeFraction{size.value, fraction.value});
    }
    const SizeKind kind = kind_given_ ? kind_ : (curve ? SizeKind::diameter : SizeKind::radius);
    return curve ? Radii::grading_curve(std::move(rows), basis, kind) : Radii::discrete(std::move(rows), basis, kind);
  }

  std::string_view spec_;
  bool modified_ = false;
  bool basis_given_ = false;
  bool kind_given_ = false;
  Basis basis_ = Basis::number;
  SizeKind kind_ = SizeKind::radius;
};

}  // namespace

Radii parse_radii(std::string_view spec) {
  return SpecParser(spec).parse();
}

SizeTable parse_size_table(std::string_view text, std::string_view source) {
  SizeTable table;
  const std::string where(source);
  const auto fail = [&where](std::size_t line, const std::string& detail) {
    throw OptionError(where + ":" + std::to_string(line) + ": " + detail);
  };
  bool header = false;
  std::size_t line_no = 0;
  for (std::size_t pos = 0; pos <= text.size();) {
    const std::size_t nl = text.find('\n', pos);
    std::string_view line = text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() + 1 : nl + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') {
      line.remove_suffix(1);
    }
    const std::string_view content = trim(line);
    if (content.empty() || content.front() == '#') {
      continue;
    }
    const std::vector<std::string_view> fields = split(content, ',');
    if (!header) {
      const std::string_view a = fields.size() == 2 ? trim(fields[0]) : std::string_view();
      const std::string_view b = fields.size() == 2 ? trim(fields[1]) : std::string_view();
      if ((a != "radius" && a != "diameter") || (b != "fraction" && b != "passing")) {
        fail(line_no,
             "expected a header 'radius,fraction', 'diameter,fraction', 'radius,passing' or "
             "'diameter,passing', got " +
                 in_quotes(content));
      }
      table.kind = a == "radius" ? SizeKind::radius : SizeKind::diameter;
      table.cumulative = b == "passing";
      header = true;
      continue;
    }
    if (fields.size() != 2) {
      fail(line_no, "expected SIZE,FRACTION (2 comma-separated numbers), got " + in_quotes(content));
    }
    const detail::Decimal size = to_double(fields[0]);
    if (size.status != detail::DecimalStatus::ok) {
      fail(line_no, number_problem(fields[0], size));
    }
    const detail::Decimal fraction = to_double(fields[1]);
    if (fraction.status != detail::DecimalStatus::ok) {
      fail(line_no, number_problem(fields[1], fraction));
    }
    const SizeFraction row{size.value, fraction.value};
    const char* size_name = to_string(table.kind);
    const char* fraction_name = table.cumulative ? "fraction passing" : "fraction";
    if (!std::isfinite(row.size) || !(row.size > 0)) {
      fail(line_no,
           std::string("the ") + size_name + " must be a finite number > 0, got " + in_quotes(trim(fields[0])));
    }
    if (!std::isfinite(row.fraction) || row.fraction < 0 || row.fraction > 1) {
      fail(line_no, std::string("the ") + fraction_name + " must be a number in [0, 1] (a fraction, not a " +
                        "percentage), got " + in_quotes(trim(fields[1])));
    }
    if (table.cumulative && !table.rows.empty()) {
      const SizeFraction& prev = table.rows.back();
      if (!(row.size > prev.size)) {
        fail(line_no, std::string("the ") + size_name + " " + format_double(row.size) +
                          " must be larger than the previous one (" + format_double(prev.size) +
                          "); give the points from the smallest size to the largest");
      }
      if (row.fraction < prev.fraction) {
        fail(line_no, "the fraction passing " + format_double(row.fraction) + " is less than the previous one (" +
                          format_double(prev.fraction) + "); a grading curve never decreases");
      }
    }
    table.rows.push_back(row);
  }
  if (!header) {
    throw OptionError(where + ": empty; expected a header line such as 'diameter,passing' and rows");
  }
  if (table.rows.empty()) {
    throw OptionError(where + ": no rows after the header");
  }
  return table;
}

SizeTable read_size_table(const std::filesystem::path& path) {
  return parse_size_table(detail::read_text_file(path), path.string());
}

Radii radii_from_table(const SizeTable& table, Basis basis) {
  return table.cumulative ? Radii::grading_curve(table.rows, basis, table.kind)
                          : Radii::discrete(table.rows, basis, table.kind);
}

}  // namespace frontpack
