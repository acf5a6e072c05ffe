// The Python module `bunraku._bunraku` (bindings/python, docs/PYTHON.md): the analysis layer
// for NumPy. The package's __init__.py wraps the stages with the parameter files' keywords.
#include "bindings/python/common.h"

#include "analysis/core/parallel.h"

namespace bunraku::python {

int resolvedThreads(int threads)
{
    if (threads < 0 || threads > analysis::kMaxThreads)
        throw Failure("threads: expected 0 (one per hardware thread) to " + std::to_string(analysis::kMaxThreads) + ", got " +
                      std::to_string(threads));
    return analysis::resolveThreads(threads);
}

} // namespace bunraku::python

PYBIND11_MODULE(_bunraku, m)
{
    namespace py = pybind11;
    using namespace bunraku::python;
    m.doc() = "The Bunraku Motion Workbench's analysis layer (C++20, Eigen) for Python: see the package bunraku.";
    m.attr("__version__") = BUNRAKU_VERSION;
    // bunraku.Error: what the command line reports as "bunraku: error: <message>" (a ValueError).
    py::register_exception<Failure>(m, "Error", PyExc_ValueError);
    bindTakes(m);
    bindStages(m);
}
