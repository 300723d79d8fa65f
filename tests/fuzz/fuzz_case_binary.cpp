// libFuzzer target: any bytes as a serialized dem.proto.Case (what
// load_case sends in binary) - parsing, validation, conversion to a world,
// a few cycles.
#include <string_view>

#include "dem/io/case_loader.h"
#include "fuzz_case.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  dem::fuzz::run_case("case_binary", [&] { return dem::io::parse_case_binary(bytes, "fuzz.case.bin"); });
  return 0;
}
