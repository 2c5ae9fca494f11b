#include "serve/mqtt_auth.hpp"

#include <openssl/evp.h>
#include <openssl/hmac.h>

#include <fmt/format.h>

namespace sreh::serve {

std::string command_signature(const std::string& token, const std::string& topic, const std::string& unsigned_payload) {
  const std::string message = topic + "\n" + unsigned_payload;
  unsigned char mac[EVP_MAX_MD_SIZE];
  unsigned int len = 0;
  HMAC(EVP_sha256(), token.data(), static_cast<int>(token.size()), reinterpret_cast<const unsigned char*>(message.data()),
       message.size(), mac, &len);
  std::string hex;
  for (unsigned int i = 0; i < len; ++i) hex += fmt::format("{:02x}", mac[i]);
  return hex;
}

bool command_signed(const std::string& token, const std::string& topic, const std::string& payload,
                    const std::string& auth_value) {
  if (auth_value.size() != 64) return false;
  const std::string quoted = "\"" + auth_value + "\"";
  const auto at = payload.find(quoted);
  if (at == std::string::npos) return false;
  std::string unsigned_payload = payload;
  unsigned_payload.replace(at, quoted.size(), "\"\"");
  const std::string want = command_signature(token, topic, unsigned_payload);
  unsigned diff = 0; // constant time
  for (std::size_t i = 0; i < want.size(); ++i) diff |= static_cast<unsigned>(want[i] ^ auth_value[i]);
  return diff == 0;
}

} // namespace sreh::serve
