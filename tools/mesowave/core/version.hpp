#pragma once

namespace mesowave {

/// `git describe --always --dirty --tags` of the tree the library was built
/// from (generated at build time by cmake/write_version.cmake).
const char* source_version();

}  // namespace mesowave
