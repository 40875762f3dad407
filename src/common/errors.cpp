#include "frontpack/errors.hpp"

#include <array>
#include <charconv>
#include <string>
#include <system_error>
#include <utility>

#include "common/format.hpp"

namespace frontpack {

CancelledError::CancelledError() : Error("cancelled") {}

IoError::IoError(const std::string& message, std::string path) : Error(message), path_(std::move(path)) {}

WktError::WktError(Kind kind, std::string detail, std::size_t offset, std::size_t line, std::size_t column,
                   std::string source)
    : Error("WKT error " + (source.empty() ? std::string() : "in '" + source + "' ") + "at line " +
            std::to_string(line) + ", column " + std::to_string(column) + " (offset " + std::to_string(offset) +
            "): " + detail),
      kind_(kind),
      detail_(std::move(detail)),
      source_(std::move(source)),
      offset_(offset),
      line_(line),
      column_(column) {}

InvalidDomainError::InvalidDomainError(Kind kind, const std::string& detail, Site site, std::optional<Site> other,
                                       std::optional<Point> where)
    : Error("invalid domain: " + detail), kind_(kind), site_(site), other_(other), where_(where) {}

DiskFileError::DiskFileError(Kind kind, std::string detail, std::string source, std::size_t line, std::size_t column)
    : Error(source + ':' + std::to_string(line) + (column > 0 ? ':' + std::to_string(column) : std::string()) + ": " +
            detail),
      kind_(kind),
      detail_(std::move(detail)),
      source_(std::move(source)),
      line_(line),
      column_(column) {}

DomainFileError::DomainFileError(Kind kind, std::string detail, std::string source, std::string entity)
    : Error(source + ": " + (entity.empty() ? std::string() : entity + ": ") + detail),
      kind_(kind),
      detail_(std::move(detail)),
      source_(std::move(source)),
      entity_(std::move(entity)) {}

const char* to_string(WktError::Kind kind) noexcept {
  switch (kind) {
    case WktError::Kind::syntax: return "syntax";
    case WktError::Kind::unsupported_geometry: return "unsupported_geometry";
    case WktError::Kind::empty_geometry: return "empty_geometry";
    case WktError::Kind::dimension: return "dimension";
    case WktError::Kind::bad_number: return "bad_number";
  }
  return "unknown";
}

const char* to_string(InvalidDomainError::Kind kind) noexcept {
  using K = InvalidDomainError::Kind;
  switch (kind) {
    case K::empty: return "empty";
    case K::non_finite_coordinate: return "non_finite_coordinate";
    case K::coordinate_out_of_range: return "coordinate_out_of_range";
    case K::unclosed_ring: return "unclosed_ring";
    case K::too_few_vertices: return "too_few_vertices";
    case K::zero_area: return "zero_area";
    case K::self_intersection: return "self_intersection";
    case K::rings_cross: return "rings_cross";
    case K::rings_overlap: return "rings_overlap";
    case K::hole_outside_shell: return "hole_outside_shell";
    case K::nested_holes: return "nested_holes";
    case K::overlapping_parts: return "overlapping_parts";
    case K::disconnected_interior: return "disconnected_interior";
  }
  return "unknown";
}

const char* to_string(DiskFileError::Kind kind) noexcept {
  using K = DiskFileError::Kind;
  switch (kind) {
    case K::empty_file: return "empty_file";
    case K::missing_header: return "missing_header";
    case K::blank_line: return "blank_line";
    case K::field_count: return "field_count";
    case K::bad_number: return "bad_number";
    case K::non_finite: return "non_finite";
    case K::bad_radius: return "bad_radius";
    case K::nonzero_z: return "nonzero_z";
    case K::unsupported_format: return "unsupported_format";
    case K::syntax: return "syntax";
    case K::missing_item: return "missing_item";
    case K::count_mismatch: return "count_mismatch";
    case K::duplicate_id: return "duplicate_id";
  }
  return "unknown";
}

const char* to_string(DomainFileError::Kind kind) noexcept {
  using K = DomainFileError::Kind;
  switch (kind) {
    case K::unreadable: return "unreadable";
    case K::empty: return "empty";
    case K::unsupported_entity: return "unsupported_entity";
    case K::open_contour: return "open_contour";
    case K::branching_contour: return "branching_contour";
    case K::bad_curve: return "bad_curve";
    case K::truncated: return "truncated";
    case K::bad_structure: return "bad_structure";
    case K::bad_number: return "bad_number";
  }
  return "unknown";
}

}  // namespace frontpack
