#pragma once
// SHA-256 (FIPS 180-4), for the fingerprints of the GitLab Code Quality report: a digest that
// identifies a finding across runs without carrying its text. Not for secrets: nothing here is
// constant-time.

#include <string>
#include <string_view>

namespace massprops::internal {

/// The SHA-256 digest of `data` as 64 lowercase hex digits. Cost: linear in the size of `data`.
std::string Sha256Hex(std::string_view data);

}  // namespace massprops::internal
