#include "common.hpp"
namespace hmira_py { void bind_arrays(nb::module_&) {} }
