#include "ecs/world.hpp"

#include <gtest/gtest.h>

namespace snow {
namespace {

struct Position {
    float x = 0, y = 0;
};
struct Tag {};

TEST(EcsWorld, CreateDestroyReuseBumpsGeneration) {
    World w;
    const Entity a = w.create();
    const Entity b = w.create();
    EXPECT_FALSE(a.is_null());
    EXPECT_NE(a, b);
    EXPECT_EQ(w.entity_count(), 2u);
    w.destroy(a);
    EXPECT_FALSE(w.alive(a));
    const Entity c = w.create();
    EXPECT_EQ(c.index(), a.index());           // slot reused ...
    EXPECT_NE(c.generation(), a.generation()); // ... with a new generation
    EXPECT_TRUE(w.alive(c));
    EXPECT_FALSE(w.alive(a));
}

TEST(EcsWorld, StaleHandleIsRejected) {
    World w;
    const Entity a = w.create();
    w.add<Position>(a, Position{1, 2});
    w.destroy(a);
    const Entity reused = w.create();
    w.add<Position>(reused, Position{3, 4});
    EXPECT_THROW(w.destroy(a), EcsError);
    EXPECT_THROW((void)w.get<Position>(a), EcsError);
    EXPECT_THROW(w.add<Position>(a), EcsError);
    EXPECT_EQ(w.try_get<Position>(a), nullptr);
    EXPECT_FALSE(w.has<Position>(a));
    EXPECT_FLOAT_EQ(w.get<Position>(reused).x, 3.0f);
    EXPECT_THROW(w.destroy(null_entity), EcsError);
}

TEST(EcsWorld, ComponentsAddGetRemove) {
    World w;
    const Entity e = w.create();
    EXPECT_FALSE(w.has<Position>(e));
    w.add<Position>(e, Position{5, 6});
    EXPECT_TRUE(w.has<Position>(e));
    EXPECT_FLOAT_EQ(w.get<Position>(e).y, 6.0f);
    w.add<Position>(e, Position{7, 8}); // replace
    EXPECT_FLOAT_EQ(w.get<Position>(e).x, 7.0f);
    EXPECT_EQ(w.count<Position>(), 1u);
    w.remove<Position>(e);
    EXPECT_FALSE(w.has<Position>(e));
    EXPECT_THROW((void)w.get<Position>(e), EcsError);
}

TEST(EcsWorld, DestroyRemovesAllComponents) {
    World w;
    const Entity e = w.create();
    w.add<Position>(e);
    w.add<Tag>(e);
    w.destroy(e);
    EXPECT_EQ(w.count<Position>(), 0u);
    EXPECT_EQ(w.count<Tag>(), 0u);
}

TEST(EcsWorld, ViewVisitsOnlyEntitiesWithAllComponentsInOrder) {
    World w;
    std::vector<Entity> tagged;
    for (int i = 0; i < 10; ++i) {
        const Entity e = w.create();
        w.add<Position>(e, Position{static_cast<float>(i), 0});
        if (i % 3 == 0) {
            w.add<Tag>(e);
            tagged.push_back(e);
        }
    }
    std::vector<Entity> seen;
    w.each<Position, Tag>([&](Entity e, Position& p, Tag&) {
        seen.push_back(e);
        p.y = 1;
    });
    EXPECT_EQ(seen, tagged);
    int updated = 0;
    w.each<Position>([&](Entity, const Position& p) { updated += p.y == 1 ? 1 : 0; });
    EXPECT_EQ(updated, 4);
}

TEST(EcsWorld, SwapRemoveKeepsLookupsValid) {
    World w;
    std::vector<Entity> es;
    for (int i = 0; i < 5; ++i) {
        es.push_back(w.create());
        w.add<Position>(es.back(), Position{static_cast<float>(i), 0});
    }
    w.remove<Position>(es[1]);
    for (int i : {0, 2, 3, 4}) {
        EXPECT_FLOAT_EQ(w.get<Position>(es[i]).x, static_cast<float>(i));
    }
}

TEST(EcsWorld, Resources) {
    World w;
    EXPECT_FALSE(w.has_resource<Position>());
    EXPECT_THROW((void)w.resource<Position>(), EcsError);
    w.set_resource<Position>(Position{1, 2});
    EXPECT_FLOAT_EQ(w.resource<Position>().y, 2.0f);
    w.erase_resource<Position>();
    EXPECT_EQ(w.try_resource<Position>(), nullptr);
}

} // namespace
} // namespace snow
