// Signed MQTT commands (issue 27): with --token-file a command may carry
// "auth": the hex HMAC-SHA256, keyed with the token, of
//   <topic> "\n" <the payload as sent, with the auth value empty ("auth": "")>
// so the token itself never travels through the broker (a "#" subscriber
// sees only signatures). A client builds its JSON with "auth": "", signs
// that text, and puts the signature into the empty string.
#pragma once
#include <string>

namespace sreh::serve {

std::string command_signature(const std::string& token, const std::string& topic, const std::string& unsigned_payload);
// Whether `payload` (as received) carries `auth_value` as a valid signature.
bool command_signed(const std::string& token, const std::string& topic, const std::string& payload,
                    const std::string& auth_value);

} // namespace sreh::serve
