// The library's side of the GDAL module: loads frontpack_ogr.so once (dlopen), calls it, and turns
// its result into polygons or a DomainFileError.
#include "domain/ogr_reader.hpp"

#include <dlfcn.h>

#include <mutex>
#include <string>
#include <string_view>

#include "common/memory_file.hpp"
#include "common/read_file.hpp"
#include "domain/geojson_numbers.hpp"
#include "frontpack/errors.hpp"

namespace frontpack::detail {

namespace {

// Where the module is: FRONTPACK_OGR_MODULE_BUILT (the build tree, for the tool and the tests run
// there) and FRONTPACK_OGR_MODULE_INSTALLED (${libdir}/frontpack), both set by src/CMakeLists.txt.
struct Module {
  OgrReadFunction* read = nullptr;
  std::string error;  // why it could not be loaded
};

const Module& module() {
  static Module m;
  static std::once_flag loaded;
  std::call_once(loaded, [] {
    for (const char* path : {FRONTPACK_OGR_MODULE_BUILT, FRONTPACK_OGR_MODULE_INSTALLED}) {
      // RTLD_LOCAL: GDAL's symbols stay out of the program's namespace. Never closed.
      if (void* handle = ::dlopen(path, RTLD_NOW | RTLD_LOCAL); handle != nullptr) {
        m.read = reinterpret_cast<OgrReadFunction*>(::dlsym(handle, "frontpack_ogr_read"));
        if (m.read != nullptr) {
          return;
        }
      }
      const char* why = ::dlerror();
      m.error += std::string(m.error.empty() ? "" : "; ") + (why != nullptr ? why : path);
    }
  });
  return m;
}

}  // namespace

GisPolygons read_ogr(const std::filesystem::path& path, const char* driver) {
  const std::string source = path.string();
  const Module& m = module();
  if (m.read == nullptr) {
    throw DomainFileError(DomainFileError::Kind::unreadable,
                          "GeoJSON and Shapefile are read by frontpack's GDAL module (frontpack_ogr.so), which could "
                          "not be loaded: " +
                              m.error,
                          source);
  }
  OgrResult result;
  if (std::string_view(driver) == "GeoJSON") {
    const std::string text = read_text_file(path);
    check_geojson_numbers(text, source);
    const MemoryFile memory(text, source, "GDAL");
    m.read(memory.path().c_str(), driver, &result);
    // GDAL's messages name the file it opened: the memory file stands for `source`.
    for (std::size_t at = 0; (at = result.message.find(memory.path(), at)) != std::string::npos;) {
      result.message.replace(at, memory.path().size(), source);
      at += source.size();
    }
  } else {
    m.read(source.c_str(), driver, &result);
  }
  if (result.error != 0) {
    throw DomainFileError(static_cast<DomainFileError::Kind>(result.error - 1), std::move(result.message), source,
                          std::move(result.entity));
  }
  return std::move(result.gis);
}

}  // namespace frontpack::detail
