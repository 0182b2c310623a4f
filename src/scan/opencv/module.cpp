// The picture module's table (picture_module.hpp): the one symbol the library looks up in it.
#include <opencv2/core.hpp>

#include "scan/opencv/module_parts.hpp"

extern "C" __attribute__((visibility("default"))) const tape::picture_module::Api* tape_picture_module_api() {
    namespace m = tape::picture_module;
#if defined(__SANITIZE_ADDRESS__)
    // LeakSanitizer cannot stop OpenCV's worker threads at a program's end once OpenCV came in by dlopen
    // (its tracer dies, exit 134): sanitized builds compute on the calling thread.
    static const bool one_thread = (cv::setNumThreads(0), true);
    (void)one_thread;
#endif
    static const m::Api api{m::abi_version, m::decode, m::encode, m::greys, m::blobs};
    return &api;
}
