// SHA-256 (FIPS 180-4) of a file or a byte string, as 64 lower-case hex digits — the same text
// `sha256sum` prints. For determinism tests: two lockstep runs with one seed must give run records
// with equal hashes.
//
//   namespace rec = swarm::record;
//   EXPECT_EQ(rec::sha256_file_hex(a + "/run.pb"), rec::sha256_file_hex(b + "/run.pb"));
//
// Thread-safe (no shared state).
#pragma once

#include <string>
#include <string_view>

namespace swarm::record {

std::string sha256_hex(std::string_view bytes);

// Throws std::runtime_error naming the file when it cannot be read.
std::string sha256_file_hex(const std::string& path);

}  // namespace swarm::record
