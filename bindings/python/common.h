#pragma once
/// Shared plumbing of the Python module (bindings/python): NumPy views of Eigen memory, results
/// and errors as Python sees them, and the one way a long call runs (GIL released, Ctrl-C
/// honoured through the analysis's RunControl stop token).

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Eigen/Core>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <thread>
#include <utility>

namespace bunraku::python {

namespace py = pybind11;

/// An analysis error on its way to Python: raised there as bunraku.Error (a ValueError) with the
/// message the command line prints after "bunraku: error: ".
struct Failure : std::runtime_error {
    explicit Failure(const std::string& message) : std::runtime_error(message) {}
};

template <class T> T unwrap(analysis::Result<T> result)
{
    if (!result.ok()) throw Failure(result.error().message);
    return std::move(result).value();
}
inline void unwrap(const analysis::Status& status)
{
    if (!status.ok()) throw Failure(status.error().message);
}

/// A shared pointer to a member of what `root` owns: the member lives as long as any Python
/// object holding it (no copy, no dangling view). The stage results are immutable; Python sees
/// them through read-only views.
template <class Member, class Root> std::shared_ptr<Member> alias(const std::shared_ptr<Root>& root, const Member& member)
{
    return std::shared_ptr<Member>(root, const_cast<Member*>(&member));
}

/// A read-only NumPy array over `data` (no copy) that keeps `owner` alive.
template <class Scalar>
py::array view(const Scalar* data, std::initializer_list<py::ssize_t> shape, std::initializer_list<py::ssize_t> strides, py::handle owner)
{
    py::array array(py::dtype::of<Scalar>(), std::vector<py::ssize_t>(shape), std::vector<py::ssize_t>(strides), data, owner);
    py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return array;
}

/// frames x channels (Eigen's column-major layout: NumPy sees a Fortran-ordered array).
template <class Scalar, int Rows, int Cols>
py::array matrixView(const Eigen::Matrix<Scalar, Rows, Cols>& m, py::handle owner)
{
    constexpr py::ssize_t size = sizeof(Scalar);
    return view<Scalar>(m.data(), {py::ssize_t(m.rows()), py::ssize_t(m.cols())}, {size, size * py::ssize_t(m.rows())}, owner);
}

template <class Scalar, int Rows>
py::array vectorView(const Eigen::Matrix<Scalar, Rows, 1>& v, py::handle owner)
{
    return view<Scalar>(v.data(), {py::ssize_t(v.size())}, {py::ssize_t(sizeof(Scalar))}, owner);
}

/// Threads the stages may use (RunControl::threads); 0 = one per hardware thread, as
/// `bunraku analyse --threads 0`.
int resolvedThreads(int threads);

/// Runs `work(control)` on a worker thread with the GIL released, while the calling thread
/// waits and, every 50 ms, takes the GIL to run Python's signal handlers (PyErr_CheckSignals:
/// only the main thread's have effect). A KeyboardInterrupt (Ctrl-C) requests the control's
/// stop; the analysis returns Cancelled at its next check and the interrupt is raised. Other
/// Python threads run meanwhile. Errors (Result errors, C++ exceptions) surface as exceptions.
template <class Work> auto runReleased(Work&& work, int threads = 1) -> decltype(work(std::declval<const analysis::RunControl&>()))
{
    using Value = decltype(work(std::declval<const analysis::RunControl&>()));
    std::stop_source stop;
    std::optional<Value> value;
    std::exception_ptr failure;
    bool interrupted = false;
    {
        py::gil_scoped_release release;
        std::mutex mutex;
        std::condition_variable finished;
        bool done = false;
        std::thread worker([&] {
            try {
                const analysis::RunControl control{stop.get_token(), {}, threads};
                value.emplace(work(control));
            } catch (...) {
                failure = std::current_exception();
            }
            std::lock_guard lock(mutex);
            done = true;
            finished.notify_all();
        });
        std::unique_lock lock(mutex);
        while (!done) {
            finished.wait_for(lock, std::chrono::milliseconds(50));
            if (done || interrupted) continue;
            lock.unlock();
            {
                py::gil_scoped_acquire acquire;
                if (PyErr_CheckSignals() != 0) {
                    interrupted = true; // the exception stays set on this thread until raised below
                    stop.request_stop();
                }
            }
            lock.lock();
        }
        lock.unlock();
        worker.join();
    }
    if (interrupted) throw py::error_already_set();
    if (failure) std::rethrow_exception(failure);
    return std::move(*value);
}

void bindTakes(py::module_& m);
void bindStages(py::module_& m);

} // namespace bunraku::python
