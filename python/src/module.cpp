// swept._swept: the C++ half of the Python module `swept` (python/swept/__init__.py wraps it).
#include "convert.h"

PYBIND11_MODULE(_swept, m) {
  m.doc() = "swept: RSS-tree distance/collision queries and the certified disassembly planner (C++ core)";
  // Bad input: swept.Error (a ValueError) with the command line's message.
  pybind11::register_exception<swept::py::InputError>(m, "Error", PyExc_ValueError);
  swept::py::bind_mesh(m);
  swept::py::bind_query(m);
  swept::py::bind_plan(m);
  swept::py::bind_assembly(m);
  m.attr("__version__") = "0.1.0";
}
