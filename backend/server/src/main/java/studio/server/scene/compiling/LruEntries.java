package studio.server.scene.compiling;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;

import studio.server.system.MemoryBudget;

/**
 * Values kept by key, the least recently used first out, each holding its size and its share of the
 * service's {@link MemoryBudget} while it is kept. Several maps may share one {@link Bound} (the mesh
 * cache's parsed meshes, models and built meshes); it counts what they hold together and evicts from
 * them in the order they were made. Not thread-safe: its owner guards it.
 */
final class LruEntries<K, V> {

    private record Entry<V>(V value, long size, MemoryBudget.Reservation memory) {
    }

    private final Map<K, Entry<V>> entries = new LinkedHashMap<>(16, 0.75f, true);
    private final Bound bound;

    private LruEntries(Bound bound) {
        this.bound = bound;
    }

    /** The value kept for {@code key}, now the most recently used; or null. */
    V get(K key) {
        Entry<V> entry = entries.get(key);
        return entry != null ? entry.value() : null;
    }

    /**
     * Keeps a value of {@code size} (in the bound's unit) that holds {@code bytes} of memory, making
     * room least recently used first; not kept if it is larger than the bound or the budget cannot
     * cover it even then.
     */
    void keep(K key, V value, long size, long bytes) {
        MemoryBudget.Reservation memory = bound.admit(size, bytes);
        if (memory != null) {
            release(entries.put(key, new Entry<>(value, size, memory)));
        }
    }

    /** Each kept key and value, least recently used first (their order is left as it is). */
    void forEach(BiConsumer<K, V> action) {
        entries.forEach((key, entry) -> action.accept(key, entry.value()));
    }

    private boolean evictOldest() {
        Iterator<Entry<V>> oldest = entries.values().iterator();
        if (!oldest.hasNext()) {
            return false;
        }
        release(oldest.next());
        oldest.remove();
        return true;
    }

    private void release(Entry<V> entry) {
        if (entry != null) {
            bound.size -= entry.size();
            entry.memory().close();
        }
    }

    /** At most so much kept (bytes, triangles) in the maps made from it, their memory reserved from a budget. */
    static final class Bound {

        private final long max;
        private final MemoryBudget memory;
        private final List<LruEntries<?, ?>> evictionOrder = new ArrayList<>();
        private long size;

        Bound(long max, MemoryBudget memory) {
            this.max = max;
            this.memory = memory;
        }

        /** A map under this bound, evicted from after those made before it are empty. */
        <K, V> LruEntries<K, V> newMap() {
            LruEntries<K, V> map = new LruEntries<>(this);
            evictionOrder.add(map);
            return map;
        }

        /** What the maps hold now. */
        long size() {
            return size;
        }

        /** Whether anything can be kept at all (a bound of 0 keeps nothing). */
        boolean keepsAny() {
            return max > 0;
        }

        private MemoryBudget.Reservation admit(long size, long bytes) {
            if (size > max) {
                return null;
            }
            while (this.size + size > max && evictOne()) {
                // evicting
            }
            MemoryBudget.Reservation reservation;
            while ((reservation = memory.tryReserve(bytes)) == null) {
                if (!evictOne()) {
                    return null;
                }
            }
            this.size += size;
            return reservation;
        }

        private boolean evictOne() {
            for (LruEntries<?, ?> map : evictionOrder) {
                if (map.evictOldest()) {
                    return true;
                }
            }
            return false;
        }
    }
}
