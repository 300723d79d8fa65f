// libFuzzer target: any bytes as a case in protobuf text format - the case
// loader, validation, conversion to a world, a few cycles.
#include <string_view>

#include "dem/io/case_loader.h"
#include "fuzz_case.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  dem::fuzz::run_case("case_text", [&] { return dem::io::parse_case_text(text, "fuzz.case.txtpb"); });
  return 0;
}
