package studio.server.scene.compiling;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

import studio.server.system.MemoryBudget;

/** The caches' one LRU: eviction by recency under a shared bound, each entry's memory held while kept. */
class LruEntriesTest {

    @Test
    void evictsTheLeastRecentlyUsedWhenTheBoundIsPassed() {
        LruEntries.Bound bound = new LruEntries.Bound(10, MemoryBudget.unlimited());
        LruEntries<String, String> map = bound.newMap();
        map.keep("a", "A", 4, 0);
        map.keep("b", "B", 4, 0);
        assertThat(map.get("a")).isEqualTo("A"); // now b is the least recently used

        map.keep("c", "C", 4, 0);

        assertThat(map.get("b")).isNull();
        assertThat(map.get("a")).isEqualTo("A");
        assertThat(map.get("c")).isEqualTo("C");
        assertThat(bound.size()).isEqualTo(8);
    }

    @Test
    void mapsMadeFirstAreEmptiedFirst() {
        LruEntries.Bound bound = new LruEntries.Bound(10, MemoryBudget.unlimited());
        LruEntries<String, String> first = bound.newMap(), second = bound.newMap();
        second.keep("old", "O", 4, 0);
        first.keep("newer", "N", 4, 0);

        second.keep("x", "X", 4, 0);

        assertThat(first.get("newer")).isNull();
        assertThat(second.get("old")).isEqualTo("O");
        assertThat(bound.size()).isEqualTo(8);
    }

    @Test
    void holdsItsMemoryWhileKeptAndKeepsNothingTheBudgetCannotCover() {
        MemoryBudget memory = new MemoryBudget(1000);
        LruEntries.Bound bound = new LruEntries.Bound(100, memory);
        LruEntries<String, String> map = bound.newMap();
        map.keep("a", "A", 1, 600);
        assertThat(memory.reserved()).isEqualTo(600);

        map.keep("b", "B", 1, 700); // only after "a" goes
        assertThat(map.get("a")).isNull();
        assertThat(map.get("b")).isEqualTo("B");
        assertThat(memory.reserved()).isEqualTo(700);

        map.keep("c", "C", 1, 2000); // more than the budget: everything goes, and it is not kept
        assertThat(map.get("c")).isNull();
        assertThat(memory.reserved()).isZero();
        assertThat(bound.size()).isZero();
    }

    @Test
    void replacingAKeyGivesBackTheOldEntrysShare() {
        MemoryBudget memory = new MemoryBudget(1000);
        LruEntries.Bound bound = new LruEntries.Bound(100, memory);
        LruEntries<String, String> map = bound.newMap();
        map.keep("a", "A", 3, 300);

        map.keep("a", "A2", 5, 100);

        assertThat(map.get("a")).isEqualTo("A2");
        assertThat(bound.size()).isEqualTo(5);
        assertThat(memory.reserved()).isEqualTo(100);
    }

    @Test
    void aBoundOfNothingKeepsNothing() {
        LruEntries.Bound bound = new LruEntries.Bound(0, MemoryBudget.unlimited());
        LruEntries<String, String> map = bound.newMap();

        map.keep("a", "A", 1, 0);

        assertThat(bound.keepsAny()).isFalse();
        assertThat(map.get("a")).isNull();
    }
}
