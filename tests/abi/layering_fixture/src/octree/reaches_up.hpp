// A lower-layer header that includes a query engine's header: the tree
// check_layering.sh must refuse (ctest layering_catches_upward_include).
#pragma once

#include "query/context.hpp"
