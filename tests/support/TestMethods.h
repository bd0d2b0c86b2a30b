#pragma once
// The shadow methods under test, read from the method table (renderer/methods/ShadowMethod.h), so
// a test that means "every method" or "every light-space flood" follows the table as it grows.

#include <renderer/methods/ShadowMethod.h>

#include <string_view>
#include <vector>

namespace fl::test {

/// True when `m` is another row's standard-flooding reference (flood-l, flood-e).
inline bool isStandardFlooding(const MethodDescriptor& m) {
    for (const MethodDescriptor& other : methodTable())
        if (other.reference == m.name) return true;
    return false;
}

/// The rows of the table that `keep` accepts, in table order.
template <class Pred>
std::vector<const MethodDescriptor*> methodsWhere(Pred keep) {
    std::vector<const MethodDescriptor*> out;
    for (const MethodDescriptor& m : methodTable())
        if (keep(m)) out.push_back(&m);
    return out;
}

/// The flooding methods working in `space`: jfa-l and flood-l (Light), jfa-e and flood-e (Eye).
inline std::vector<const MethodDescriptor*> floodingMethods(MethodSpace space) {
    return methodsWhere(
        [space](const MethodDescriptor& m) { return m.floods && m.space == space; });
}

} // namespace fl::test
