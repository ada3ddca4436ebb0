// libFuzzer target for the .bake reader (both flavours): no input may crash or allocate without bound, and a bake
// that reads must write and read back to the same frames.
#include "io/BakeFile.h"

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    rl::Result<rl::Bake> bake = rl::readBake(text, "fuzz.bake");
    if (!bake)
        return 0;
    std::ostringstream out;
    rl::writeBake(*bake, out);
    rl::Result<rl::Bake> again = rl::readBake(out.str(), "again.bake");
    if (!again || again->frameCount() != bake->frameCount() || again->bodyCount() != bake->bodyCount())
        std::abort();
    for (size_t f = 0; f < bake->frameCount(); ++f)
        for (size_t b = 0; b < bake->bodyCount(); ++b)
            if (again->position(f, b) != bake->position(f, b) || again->rotation(f, b) != bake->rotation(f, b))
                std::abort();
    return 0;
}
