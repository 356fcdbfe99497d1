// libFuzzer harness of the glTF and GLB reader (see fuzz_loader.h; corpus in fuzz/corpus/gltf/, run
// by scripts/fuzz.sh). Every input is read both as .gltf (JSON) and as .glb (binary container): one
// of the two fails at once on the first bytes, so both corpora share one harness.
#include "fuzz_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    hlens_fuzz::load(data, size, "fuzz.gltf");
    hlens_fuzz::load(data, size, "fuzz.glb");
    return 0;
}
