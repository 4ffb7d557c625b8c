// libFuzzer target: the arm server's parser of a client's line (core/button/PROTOCOL.md, the
// token handshake {"token": "..."}) and the token check, on any bytes.
#include "core/button/arm_protocol.h"
#include "tests/fuzz/fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string line = sightline::fuzz::AsText(data, size);
  const std::optional<std::string> token = sightline::ParseTokenLine(line);
  if (token) (void)sightline::TokensMatch(*token, "s3cret-token");
  return 0;
}
