#pragma once
// Base64 (RFC 4648 section 4, with padding): binary files carried inside text, such as the .glb
// trees of the HTML report, which a page opened from file:// can only load as scripts.
#include <string>
#include <string_view>

namespace fspm::cli {

std::string base64_encode(std::string_view bytes);

}  // namespace fspm::cli
