#pragma once
// What Crumple was built from, for the listing header and NAME.summary.json: the project version and the git
// commit of the source tree ("-modified" when it had uncommitted changes, "unknown" outside a git checkout).
// Written at every build by cmake/BuildInfo.cmake.
namespace crumple::build {
const char* version();
const char* commit();
}  // namespace crumple::build
