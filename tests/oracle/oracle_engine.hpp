// The engine the oracle tests query: OPX_ENGINE_DIRECT, or the amortized
// engine when OPX_ORACLE_ENGINE=amortized (refinement paths per query from
// OPX_ORACLE_REFINE, default 1), so every oracle test runs on both.
#pragma once

#include <octoprox/octoprox.h>

#include <cstdlib>
#include <cstring>

inline opx_status oracle_create_query(opx_query **out) {
    opx_query_options options = OPX_QUERY_OPTIONS_INIT;
    const char *engine = std::getenv("OPX_ORACLE_ENGINE");
    if (engine != nullptr && std::strcmp(engine, "amortized") == 0) {
        options.engine = OPX_ENGINE_AMORTIZED;
        if (const char *refine = std::getenv("OPX_ORACLE_REFINE"))
            options.refine_steps = static_cast<uint32_t>(std::strtoul(refine, nullptr, 10));
    }
    return opx_query_create(&options, out);
}
