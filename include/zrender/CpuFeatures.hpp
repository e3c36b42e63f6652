#pragma once

namespace zrender {

// Whether this CPU runs AVX2 code: the vector pixel loops are used only then, and they give the
// same bits as their scalar versions (each is tested against its scalar twin).
bool cpuHasAvx2();

}  // namespace zrender
