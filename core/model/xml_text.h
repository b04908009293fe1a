#pragma once
// Text handed to TinyXML (our SRDF reader, and urdfdom for URDF).
#include <string>

namespace demoplan {

// The text followed by NUL bytes. TinyXML 2.6.2 (Debian 12's libtinyxml) steps over a UTF-8 lead
// byte's whole sequence without looking for the end of the text, so text that ends inside a
// sequence made it read past the end of the buffer (AddressSanitizer, found by fuzz_srdf). The
// padding keeps every such read inside the buffer; TinyXML stops at the first NUL, so it reads
// the same document.
inline std::string padded_for_tinyxml(const std::string& xml) { return xml + std::string(8, '\0'); }

}  // namespace demoplan
