#include "base/avx2.hpp"

namespace octoprox {

bool cpu_has_avx2() {
#if defined(OPX_AVX2_LANES)
    static const bool available = __builtin_cpu_supports("avx2");
    return available;
#else
    return false;
#endif
}

}  // namespace octoprox
