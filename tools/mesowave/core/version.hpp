#pragma once

namespace mesowave {

/// `git describe` of the last commit that changed the code the library was
/// built from (tools/, cmake/, CMakeLists.txt, db/schema.sql), "-dirty" if it has
/// uncommitted changes (generated at build time by cmake/write_version.cmake).
const char* source_version();

}  // namespace mesowave
