// libFuzzer harness of the PLY reader (see fuzz_loader.h; corpus in fuzz/corpus/ply/, run by scripts/fuzz.sh).
#include "fuzz_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    hlens_fuzz::load(data, size, "fuzz.ply");
    return 0;
}
