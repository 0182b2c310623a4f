// The picture module's table (picture_module.hpp): the one symbol the library looks up in it.
#include <dlfcn.h>

#include <opencv2/core.hpp>

#include "scan/opencv/module_parts.hpp"

extern "C" __attribute__((visibility("default"))) const tape::picture_module::Api* tape_picture_module_api() {
    namespace m = tape::picture_module;
    // LeakSanitizer cannot stop OpenCV's worker threads at a program's end once OpenCV came in by dlopen
    // (its tracer dies, exit 134): in a sanitized program (the tests, the fuzzers: AddressSanitizer's
    // runtime is in the process, whatever compiled this module) OpenCV computes on the calling thread.
    static const bool one_thread = dlsym(RTLD_DEFAULT, "__asan_init") && (cv::setNumThreads(0), true);
    (void)one_thread;
    static const m::Api api{m::abi_version, m::decode, m::encode, m::greys, m::blobs};
    return &api;
}
