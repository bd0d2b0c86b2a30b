// gpu/LiveObjects.h: the count of live GL objects follows what is created and freed, whatever
// the driver does with freed names (the soak tests rely on it to see a leak).

#include "GlTest.h"

#include <gpu/LiveObjects.h>

#include <vector>

namespace fl::test {
namespace {

class LiveObjects : public GlTest {};

TEST_F(LiveObjects, CountsFollowCreationAndRelease) {
    const gl::ObjectCounts before = gl::countLiveObjects();
    const auto textures = static_cast<std::size_t>(gl::ObjectKind::Texture);
    const auto buffers = static_cast<std::size_t>(gl::ObjectKind::Buffer);
    {
        std::vector<gl::Texture> t;
        for (int i = 0; i < 5; ++i) t.emplace_back(GL_R32F, 4, 4);
        gl::Buffer b(64, nullptr, 0);
        const gl::ObjectCounts during = gl::countLiveObjects();
        EXPECT_EQ(during.live[textures], before.live[textures] + 5);
        EXPECT_EQ(during.live[buffers], before.live[buffers] + 1);
        EXPECT_EQ(during.total(), before.total() + 6) << during.text();
        // Two freed and two made: names may be reused or not, the count is the same.
        t.erase(t.begin(), t.begin() + 2);
        t.emplace_back(GL_R32F, 4, 4);
        t.emplace_back(GL_R32F, 4, 4);
        EXPECT_EQ(gl::countLiveObjects().live[textures], before.live[textures] + 5);
    }
    EXPECT_EQ(gl::countLiveObjects().live, before.live);
}

} // namespace
} // namespace fl::test
