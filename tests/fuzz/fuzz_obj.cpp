// libFuzzer entry point for the OBJ reader: any bytes must give objects or an Error, never a crash or a hang.
// Build with -DRL_FUZZ=ON (clang) and run e.g. `fuzz_obj -max_total_time=60 tests/data/import/obj`.
#include "io/ObjReader.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    rl::Result<rl::ObjFile> file = rl::readObj(text, "fuzz.obj");
    if (!file.ok()) {
        // Every error names the file, so the user knows which input was bad.
        if (file.error().file != "fuzz.obj" || file.error().message.empty())
            std::abort();
        return 0;
    }
    // What the reader promises: bodies with faces, indices in range, finite vertices and means.
    if (file->objects.empty())
        std::abort();
    for (const rl::ObjObject& o : file->objects) {
        if (o.triangles.empty() || o.vertices.empty() || o.vertices.size() != o.fileVertexIndices.size())
            std::abort();
        for (const auto& t : o.triangles)
            for (uint32_t i : t)
                if (i >= o.vertices.size())
                    std::abort();
        for (uint32_t i : o.fileVertexIndices)
            if (i >= file->vertexCount)
                std::abort();
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(o.vertexMean[k]))
                std::abort();
    }
    return 0;
}
