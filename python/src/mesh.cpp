#include "common.hpp"
namespace hmira_py { void bind_mesh(nb::module_&) {} }
