#include <octoprox/common.h>

#define OPX_STRINGIFY_(x) #x
#define OPX_STRINGIFY(x) OPX_STRINGIFY_(x)

extern "C" OPX_API const char *opx_version(void) {
    return OPX_STRINGIFY(OPX_VERSION_MAJOR) "." OPX_STRINGIFY(OPX_VERSION_MINOR) "." OPX_STRINGIFY(
        OPX_VERSION_PATCH);
}

extern "C" OPX_API uint32_t opx_version_number(void) { return OPX_VERSION_NUMBER; }
