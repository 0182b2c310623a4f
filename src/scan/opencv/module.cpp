// The picture module's table (picture_module.hpp): the one symbol the library looks up in it.
#include "scan/opencv/module_parts.hpp"

extern "C" __attribute__((visibility("default"))) const tape::picture_module::Api* tape_picture_module_api() {
    namespace m = tape::picture_module;
    static const m::Api api{m::abi_version, m::decode, m::encode, m::greys, m::blobs};
    return &api;
}
