// The GDAL module (frontpack_ogr.so): GeoJSON and Shapefile polygons, loaded by the library with
// dlopen on first use (domain/ogr_reader.hpp says why). It links GDAL and nothing of frontpack's:
// errors cross the boundary as data (OgrResult), not as exceptions.
#include "domain/ogr_reader.hpp"

#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <exception>
#include <memory>
#include <mutex>
#include <string>

#include "frontpack/errors.hpp"  // DomainFileError::Kind only (an enum: no symbol)

namespace frontpack::detail {

namespace {

using Kind = DomainFileError::Kind;

// An error to report: the module's own exception, turned into OgrResult at the entry point.
struct Failure {
  Kind kind = Kind::unreadable;
  std::string message{};
  std::string entity{};
};

// GDAL reports problems through an error handler that prints by default: a quiet one on this
// thread while we read (the library never prints), and the last message taken into our errors.
class QuietGdal {
 public:
  QuietGdal() {
    static std::once_flag registered;
    std::call_once(registered, [] { GDALAllRegister(); });
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  ~QuietGdal() { CPLPopErrorHandler(); }
  QuietGdal(const QuietGdal&) = delete;
  QuietGdal& operator=(const QuietGdal&) = delete;
};

std::string last_gdal_message() {
  const char* m = CPLGetLastErrorMsg();
  return m != nullptr && *m != '\0' ? std::string(": ") + m : std::string();
}

Ring ring_of(const OGRLinearRing& r) {
  Ring out;
  out.reserve(static_cast<std::size_t>(r.getNumPoints()));
  for (int i = 0; i < r.getNumPoints(); ++i) {
    out.push_back({r.getX(i), r.getY(i)});
  }
  return out;
}

void add_polygon(const OGRPolygon& poly, const std::string& name, GisPolygons& out) {
  Polygon p;
  std::vector<std::string> names;
  if (const OGRLinearRing* outer = poly.getExteriorRing(); outer != nullptr) {
    p.outer = ring_of(*outer);
  }
  names.push_back(name + ", outer ring");
  for (int k = 0; k < poly.getNumInteriorRings(); ++k) {
    p.holes.push_back(ring_of(*poly.getInteriorRing(k)));
    names.push_back(name + ", hole " + std::to_string(k + 1));
  }
  out.polygons.push_back(std::move(p));
  out.ring_names.push_back(std::move(names));
}

GisPolygons read(const std::string& source, const char* driver) {
  const QuietGdal quiet;
  const char* const drivers[] = {driver, nullptr};
  const std::unique_ptr<GDALDataset> ds(
      GDALDataset::Open(source.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers, nullptr, nullptr));
  if (!ds) {
    throw Failure{Kind::unreadable, std::string("GDAL could not read the file as ") + driver + last_gdal_message()};
  }
  GisPolygons out;
  for (OGRLayer* layer : ds->GetLayers()) {
    layer->ResetReading();
    for (const auto& feature : *layer) {
      const std::string name =
          "layer " + std::string(layer->GetName()) + ", feature " + std::to_string(feature->GetFID());
      const OGRGeometry* g = feature->GetGeometryRef();
      if (g == nullptr || g->IsEmpty()) {
        continue;  // a feature without geometry (attributes only) adds nothing
      }
      const OGRwkbGeometryType type = wkbFlatten(g->getGeometryType());
      if (type == wkbPolygon) {
        add_polygon(*g->toPolygon(), name, out);
      } else if (type == wkbMultiPolygon) {
        const OGRMultiPolygon* mp = g->toMultiPolygon();
        for (int k = 0; k < mp->getNumGeometries(); ++k) {
          add_polygon(*mp->getGeometryRef(k), name + ", polygon " + std::to_string(k), out);
        }
      } else {
        throw Failure{Kind::unsupported_entity,
                      std::string("geometry type ") + OGRGeometryTypeToName(g->getGeometryType()) +
                          "; frontpack reads Polygon and MultiPolygon features",
                      name};
      }
    }
  }
  if (CPLGetLastErrorType() >= CE_Failure) {
    throw Failure{Kind::unreadable, "GDAL failed while reading" + last_gdal_message()};
  }
  if (out.polygons.empty()) {
    throw Failure{Kind::empty, "no Polygon or MultiPolygon feature"};
  }
  return out;
}

}  // namespace

}  // namespace frontpack::detail

extern "C" __attribute__((visibility("default"))) void frontpack_ogr_read(const char* path, const char* driver,
                                                                          frontpack::detail::OgrResult* out) {
  using frontpack::detail::Failure;
  try {
    out->gis = frontpack::detail::read(path, driver);
  } catch (const Failure& f) {
    out->error = 1 + static_cast<int>(f.kind);
    out->message = f.message;
    out->entity = f.entity;
  } catch (const std::exception& e) {
    out->error = 1 + static_cast<int>(frontpack::DomainFileError::Kind::unreadable);
    out->message = std::string("GDAL: ") + e.what();
  }
}
