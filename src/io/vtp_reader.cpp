// Reader of VTK XML PolyData (.vtp): what write_vtp writes, and what VTK's vtkXMLPolyDataWriter
// and ParaView write (ascii, binary inline base64, appended raw or base64; uncompressed). A disk
// is a point: its centre from Points, its radius from a point data array.
#include <cmath>
#include <cstdint>
#include <istream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/format.hpp"
#include "common/numbers.hpp"
#include "common/read_file.hpp"
#include "common/text.hpp"
#include "frontpack/io.hpp"
#include "io/vtk_binary.hpp"

namespace frontpack {

namespace {

using Kind = DiskFileError::Kind;
using detail::VtkType;

// The radius arrays looked for when none is named, in this order; the last two hold diameters.
constexpr std::string_view kRadiusNames[] = {"radius", "Radius", "diameter", "Diameter"};

struct Attribute {
  std::string_view name;
  std::string_view value;
};

// A DataArray element of Points or PointData: its attributes and its text (the text directly in
// it, in pieces when child elements such as InformationKey interrupt it; views into the file).
struct ArrayRef {
  std::string name;
  std::string type;
  std::string format;
  std::string offset;
  std::string components = "1";
  std::size_t at = 0;  // offset of its start tag in the file
  std::vector<std::string_view> text;
};

struct Piece {
  std::uint64_t points = 0;
  std::size_t at = 0;
  std::optional<ArrayRef> coordinates;
  std::vector<ArrayRef> point_data;
};

class VtpFile {
 public:
  VtpFile(std::string text, std::string_view source, std::string_view radius_array)
      : s_(std::move(text)), source_(source.empty() ? "<input>" : source), radius_array_(radius_array) {}

  std::vector<Disk> read();

 private:
  [[nodiscard]] std::size_t line_at(std::size_t pos) const {
    std::size_t line = 1;
    for (std::size_t i = 0; i < pos && i < s_.size(); ++i) {
      if (s_[i] == '\n') {
        ++line;
      }
    }
    return line;
  }
  [[noreturn]] void fail(Kind kind, std::size_t pos, const std::string& detail) const {
    throw DiskFileError(kind, detail, source_, line_at(pos));
  }
  [[noreturn]] void fail_array(Kind kind, const ArrayRef& a, std::size_t pos, const std::string& detail) const {
    fail(kind, pos, "<DataArray Name=" + detail::quote_text(a.name) + ">: " + detail);
  }

  void scan();
  std::size_t start_tag(std::size_t lt, std::vector<std::string_view>& stack);
  void vtk_file_tag(std::string_view name, const std::vector<Attribute>& attrs, std::size_t lt);
  void piece_tag(const std::vector<Attribute>& attrs, std::size_t lt);
  void data_array_tag(const std::vector<Attribute>& attrs, std::size_t lt, bool coordinates);
  std::vector<Attribute> attributes(std::string_view body, std::size_t at) const;
  std::vector<double> values(const ArrayRef& a, std::uint64_t count) const;
  std::vector<double> ascii_values(const ArrayRef& a, VtkType type, std::uint64_t count) const;
  const ArrayRef& radius_of(const Piece& p, bool& diameter) const;

  std::string s_;
  std::string source_;
  std::string radius_array_;
  bool vtk_file_ = false;
  bool poly_data_ = false;
  std::string compressor_;
  detail::BinaryLayout layout_;
  std::vector<Piece> pieces_;
  // The DataArray whose text is being read, by position: a pointer into pieces_ would dangle
  // once a later element (malformed nesting) grows pieces_ or a piece's point_data.
  struct OpenArray {
    std::size_t piece = 0;
    std::size_t array = 0;  // in point_data, unless coordinates
    bool coordinates = false;
    bool open = false;
  };
  OpenArray open_{};
  ArrayRef& open_array() {
    Piece& p = pieces_[open_.piece];
    return open_.coordinates ? *p.coordinates : p.point_data[open_.array];
  }
  std::optional<std::size_t> appended_;  // offset of the first byte after '_'
  std::string appended_encoding_;
};

std::string attr(const std::vector<Attribute>& attrs, std::string_view name, std::string fallback = {}) {
  for (const Attribute& a : attrs) {
    if (a.name == name) {
      return std::string(a.value);
    }
  }
  return fallback;
}

std::vector<Attribute> VtpFile::attributes(std::string_view body, std::size_t at) const {
  std::vector<Attribute> out;
  std::size_t i = 0;
  while (true) {
    while (i < body.size() && detail::is_c_space(body[i])) {
      ++i;
    }
    if (i >= body.size()) {
      return out;
    }
    const std::size_t eq = body.find('=', i);
    const std::size_t quote = eq == std::string_view::npos ? eq : body.find_first_not_of(" \t\r\n", eq + 1);
    if (quote == std::string_view::npos || (body[quote] != '"' && body[quote] != '\'')) {
      fail(Kind::syntax, at, "malformed XML attribute " + detail::quote_text(body.substr(i)));
    }
    const std::size_t close = body.find(body[quote], quote + 1);
    if (close == std::string_view::npos) {
      fail(Kind::syntax, at, "unterminated XML attribute value " + detail::quote_text(body.substr(i)));
    }
    out.push_back(
        {detail::trim(body.substr(i, eq - i), detail::is_c_space), body.substr(quote + 1, close - quote - 1)});
    i = close + 1;
  }
}

// A start tag at `lt` ('<' of "<name ...>"); returns the offset after its '>'.
std::size_t VtpFile::start_tag(std::size_t lt, std::vector<std::string_view>& stack) {
  const std::size_t gt = s_.find('>', lt);
  if (gt == std::string::npos) {
    fail(Kind::syntax, lt, "unterminated XML tag");
  }
  std::string_view body(s_.data() + lt + 1, gt - lt - 1);
  const bool self_closing = !body.empty() && body.back() == '/';
  if (self_closing) {
    body.remove_suffix(1);
  }
  std::size_t name_end = 0;
  while (name_end < body.size() && !detail::is_c_space(body[name_end])) {
    ++name_end;
  }
  const std::string_view name = body.substr(0, name_end);
  const std::vector<Attribute> attrs = attributes(body.substr(name_end), lt);
  const std::string_view parent = stack.empty() ? std::string_view() : stack.back();
  if (stack.empty()) {
    vtk_file_tag(name, attrs, lt);
  } else if (name == "PolyData" && parent == "VTKFile") {
    poly_data_ = true;
  } else if (name == "Piece" && parent == "PolyData") {
    piece_tag(attrs, lt);
  } else if (name == "DataArray" && (parent == "Points" || parent == "PointData") && !pieces_.empty()) {
    data_array_tag(attrs, lt, parent == "Points");
  } else if (name == "AppendedData" && parent == "VTKFile") {
    appended_encoding_ = attr(attrs, "encoding");
    const std::size_t underscore = s_.find_first_not_of(" \t\r\n", gt + 1);
    if (underscore == std::string::npos || s_[underscore] != '_') {
      fail(Kind::syntax, lt, "<AppendedData>: expected '_' before the data");
    }
    appended_ = underscore + 1;
    return s_.size();  // raw data may hold any byte: nothing after it is XML that matters
  }
  if (!self_closing) {
    stack.push_back(name);
  } else if (open_.open && name == "DataArray") {
    open_.open = false;
  }
  return gt + 1;
}

// The root element: a VTKFile of PolyData, its byte order, header type and compressor.
void VtpFile::vtk_file_tag(std::string_view name, const std::vector<Attribute>& attrs, std::size_t lt) {
  if (name != "VTKFile") {
    fail(Kind::syntax, lt, "expected <VTKFile> as the root element, got " + detail::quote_text(name));
  }
  const std::string type = attr(attrs, "type");
  if (type != "PolyData") {
    fail(Kind::unsupported_format, lt,
         "<VTKFile type=" + detail::quote_text(type) + ">: frontpack reads VTK PolyData (.vtp) files");
  }
  const std::string order = attr(attrs, "byte_order", "LittleEndian");
  const std::string header = attr(attrs, "header_type", "UInt32");
  if ((order != "LittleEndian" && order != "BigEndian") || (header != "UInt32" && header != "UInt64")) {
    fail(Kind::unsupported_format, lt,
         "<VTKFile>: byte_order " + detail::quote_text(order) + ", header_type " + detail::quote_text(header) +
             " (expected LittleEndian or BigEndian, UInt32 or UInt64)");
  }
  layout_ = {header == "UInt64", order == "BigEndian"};
  compressor_ = attr(attrs, "compressor");
  vtk_file_ = true;
}

// A Piece of PolyData and its number of points.
void VtpFile::piece_tag(const std::vector<Attribute>& attrs, std::size_t lt) {
  Piece piece;
  piece.at = lt;
  const std::string n = attr(attrs, "NumberOfPoints", "0");
  const detail::Decimal d = detail::parse_decimal(n);
  if (d.status != detail::DecimalStatus::ok || !(d.value >= 0) ||
      d.value != static_cast<double>(static_cast<std::uint64_t>(d.value)) || d.value > 1e12) {
    fail(Kind::bad_number, lt, "<Piece NumberOfPoints=" + detail::quote_text(n) + ">: expected a whole number");
  }
  piece.points = static_cast<std::uint64_t>(d.value);
  pieces_.push_back(std::move(piece));
}

// A DataArray of the last piece's Points (the coordinates) or PointData: its text is read next.
void VtpFile::data_array_tag(const std::vector<Attribute>& attrs, std::size_t lt, bool coordinates) {
  ArrayRef a{attr(attrs, "Name"),
             attr(attrs, "type"),
             attr(attrs, "format"),
             attr(attrs, "offset"),
             attr(attrs, "NumberOfComponents", "1"),
             lt,
             {}};
  Piece& piece = pieces_.back();
  if (coordinates) {
    piece.coordinates = std::move(a);
    open_ = {pieces_.size() - 1, 0, true, true};
  } else {
    piece.point_data.push_back(std::move(a));
    open_ = {pieces_.size() - 1, piece.point_data.size() - 1, false, true};
  }
}

void VtpFile::scan() {
  std::vector<std::string_view> stack;
  std::size_t pos = 0;
  while (pos < s_.size()) {
    const std::size_t lt = s_.find('<', pos);
    if (open_.open && !stack.empty() && stack.back() == "DataArray") {
      open_array().text.push_back(std::string_view(s_).substr(pos, (lt == std::string::npos ? s_.size() : lt) - pos));
    }
    if (lt == std::string::npos) {
      break;
    }
    const std::string_view rest = std::string_view(s_).substr(lt);
    const auto skip_to = [&](std::string_view end) {
      const std::size_t e = s_.find(end, lt);
      if (e == std::string::npos) {
        fail(Kind::syntax, lt, "unterminated XML " + detail::quote_text(rest.substr(0, 4)));
      }
      return e + end.size();
    };
    if (rest.starts_with("<?")) {
      pos = skip_to("?>");
    } else if (rest.starts_with("<!--")) {
      pos = skip_to("-->");
    } else if (rest.starts_with("</")) {
      pos = skip_to(">");
      const std::string_view name = detail::trim(rest.substr(2, pos - lt - 3), detail::is_c_space);
      if (stack.empty() || stack.back() != name) {
        const std::string open = stack.empty() ? std::string("any open element") : detail::quote_text(stack.back());
        fail(Kind::syntax, lt, "closing tag " + detail::quote_text(name) + " does not match the open element " + open);
      }
      if (name == "DataArray" && open_.open && stack.size() >= 2 &&
          (stack[stack.size() - 2] == "Points" || stack[stack.size() - 2] == "PointData")) {
        open_.open = false;
      }
      stack.pop_back();
    } else {
      pos = start_tag(lt, stack);
    }
  }
  if (!vtk_file_) {
    fail(s_.find_first_not_of(" \t\r\n") == std::string::npos ? Kind::empty_file : Kind::syntax, s_.size(),
         "no <VTKFile> element (expected a VTK XML PolyData file)");
  }
  if (!appended_ && !stack.empty()) {
    fail(Kind::syntax, s_.size(), "the file ends inside the element " + detail::quote_text(stack.back()));
  }
  if (!poly_data_) {
    fail(Kind::missing_item, s_.size(), "no <PolyData> element in <VTKFile>");
  }
}

std::vector<double> VtpFile::ascii_values(const ArrayRef& a, VtkType type, std::uint64_t count) const {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(count));
  for (const std::string_view chunk : a.text) {
    std::size_t i = 0;
    while (i < chunk.size()) {
      while (i < chunk.size() && detail::is_c_space(chunk[i])) {
        ++i;
      }
      const std::size_t start = i;
      while (i < chunk.size() && !detail::is_c_space(chunk[i])) {
        ++i;
      }
      if (i == start) {
        break;
      }
      const std::string_view token = chunk.substr(start, i - start);
      const std::size_t at = static_cast<std::size_t>(token.data() - s_.data());
      if (out.size() == count) {
        fail_array(Kind::count_mismatch, a, at, "more than the " + std::to_string(count) + " values expected");
      }
      const detail::Decimal d = detail::parse_decimal(token);
      if (d.status == detail::DecimalStatus::overflow || d.status == detail::DecimalStatus::underflow) {
        fail_array(Kind::bad_number, a, at, detail::out_of_range(token, d.status));
      }
      if (d.status != detail::DecimalStatus::ok ||
          (type != VtkType::float32 && type != VtkType::float64 && token.find_first_of(".eE") != std::string::npos)) {
        fail_array(Kind::bad_number, a, at, detail::quote_text(token) + " is not a number of type " + a.type);
      }
      if (!std::isfinite(d.value)) {
        // Named here, at its own line and text (a binary array's are caught per point below).
        fail_array(Kind::non_finite, a, at, detail::quote_text(token) + " is not a finite number");
      }
      // A Float32 array's text is what VTK prints for a float: read it as a float, as VTK does.
      out.push_back(type == VtkType::float32 ? static_cast<double>(static_cast<float>(d.value)) : d.value);
    }
  }
  if (out.size() != count) {
    fail_array(Kind::count_mismatch, a, a.at,
               "expected " + std::to_string(count) + " values, got " + std::to_string(out.size()));
  }
  return out;
}

std::vector<double> VtpFile::values(const ArrayRef& a, std::uint64_t count) const {
  const std::optional<VtkType> type = detail::vtk_type(a.type);
  if (!type) {
    fail_array(Kind::unsupported_format, a, a.at, "type " + detail::quote_text(a.type) + " is not a VTK number type");
  }
  if (a.format == "ascii") {
    return ascii_values(a, *type, count);
  }
  if (a.format != "binary" && a.format != "appended") {
    fail_array(Kind::unsupported_format, a, a.at,
               "format " + detail::quote_text(a.format) + " (expected ascii, binary or appended)");
  }
  if (!compressor_.empty()) {
    fail_array(Kind::unsupported_format, a, a.at,
               "compressed data (" + compressor_ +
                   ") is not read by frontpack; write the file uncompressed (vtkXMLWriter SetCompressorTypeToNone, "
                   "ParaView: Save Data, Compressor Type None) or in ascii mode");
  }
  std::string bytes;
  std::size_t bad_at = 0;
  if (a.format == "binary") {
    std::string encoded;
    for (const std::string_view chunk : a.text) {
      encoded.append(chunk);
    }
    auto decoded = detail::decode_base64(encoded, bad_at);
    if (!decoded) {
      fail_array(Kind::bad_number, a, a.at, "invalid base64 data");
    }
    bytes = std::move(*decoded);
  } else {
    const detail::Decimal off = detail::parse_decimal(a.offset);
    if (!appended_ || off.status != detail::DecimalStatus::ok || !(off.value >= 0) ||
        off.value > static_cast<double>(s_.size() - *appended_)) {
      fail_array(Kind::missing_item, a, a.at,
                 "appended data at offset " + detail::quote_text(a.offset) + " is not in the <AppendedData> section");
    }
    const std::size_t start = *appended_ + static_cast<std::size_t>(off.value);
    if (appended_encoding_ == "raw") {
      bytes = s_.substr(start);
    } else if (appended_encoding_ == "base64") {
      const std::size_t end = s_.find('<', start);
      auto decoded = detail::decode_base64(std::string_view(s_).substr(start, end - start), bad_at);
      if (!decoded) {
        fail_array(Kind::bad_number, a, start + bad_at, "invalid base64 data in <AppendedData>");
      }
      bytes = std::move(*decoded);
    } else {
      fail_array(Kind::unsupported_format, a, a.at,
                 "<AppendedData encoding=" + detail::quote_text(appended_encoding_) + "> (expected raw or base64)");
    }
  }
  std::vector<double> out;
  const std::string error = detail::decode_block(bytes, layout_, *type, static_cast<std::size_t>(count), out);
  if (!error.empty()) {
    fail_array(Kind::count_mismatch, a, a.at, error);
  }
  return out;
}

const ArrayRef& VtpFile::radius_of(const Piece& p, bool& diameter) const {
  const auto find = [&](std::string_view name) -> const ArrayRef* {
    for (const ArrayRef& a : p.point_data) {
      if (a.name == name) {
        return &a;
      }
    }
    return nullptr;
  };
  if (!radius_array_.empty()) {
    if (const ArrayRef* a = find(radius_array_)) {
      diameter = false;
      return *a;
    }
  } else {
    for (std::size_t k = 0; k < std::size(kRadiusNames); ++k) {
      if (const ArrayRef* a = find(kRadiusNames[k])) {
        diameter = k >= 2;
        return *a;
      }
    }
  }
  std::string have;
  for (const ArrayRef& a : p.point_data) {
    have += (have.empty() ? "" : ", ") + detail::quote_text(a.name);
  }
  fail(Kind::missing_item, p.at,
       "<Piece>: no point data array " +
           (radius_array_.empty() ? std::string("'radius', 'Radius', 'diameter' or 'Diameter'")
                                  : detail::quote_text(radius_array_)) +
           " for the radii (point data arrays: " + (have.empty() ? std::string("none") : have) + ")");
}

std::vector<Disk> VtpFile::read() {
  scan();
  std::vector<Disk> disks;
  for (const Piece& p : pieces_) {
    if (p.points == 0) {
      continue;
    }
    if (!p.coordinates) {
      fail(Kind::missing_item, p.at, "<Piece>: no <Points> array");
    }
    const ArrayRef& c = *p.coordinates;
    if (c.components != "3") {
      fail_array(Kind::field_count, c, c.at,
                 "NumberOfComponents=" + detail::quote_text(c.components) + " (points have 3 coordinates)");
    }
    bool diameter = false;
    const ArrayRef& r = radius_of(p, diameter);
    if (r.components != "1") {
      fail_array(Kind::field_count, r, r.at,
                 "NumberOfComponents=" + detail::quote_text(r.components) + " (a radius is one number per point)");
    }
    const std::vector<double> xyz = values(c, 3 * p.points);
    const std::vector<double> radii = values(r, p.points);
    for (std::size_t i = 0; i < radii.size(); ++i) {
      const double x = xyz[3 * i];
      const double y = xyz[3 * i + 1];
      const double rad = diameter ? radii[i] / 2 : radii[i];
      if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(xyz[3 * i + 2]) || !std::isfinite(rad)) {
        fail_array(Kind::non_finite, std::isfinite(rad) ? c : r, std::isfinite(rad) ? c.at : r.at,
                   "point " + std::to_string(i) + " has a value that is not finite");
      }
      if (xyz[3 * i + 2] != 0) {
        fail_array(Kind::nonzero_z, c, c.at,
                   "point " + std::to_string(i) + ": z must be 0 (frontpack's disks are planar), got " +
                       detail::format_double(xyz[3 * i + 2]));
      }
      if (!(rad > 0)) {
        fail_array(Kind::bad_radius, r, r.at,
                   "point " + std::to_string(i) + ": radius must be > 0, got " + detail::format_double(rad));
      }
      disks.push_back(Disk{{x, y}, rad});
    }
  }
  return disks;
}

}  // namespace

std::vector<Disk> read_vtp(std::istream& in, std::string_view source_name, std::string_view radius_array) {
  std::string text = detail::read_bounded(in, source_name);
  return VtpFile(std::move(text), source_name, radius_array).read();
}

}  // namespace frontpack
