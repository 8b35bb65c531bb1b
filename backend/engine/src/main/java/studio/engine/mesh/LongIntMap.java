package studio.engine.mesh;

import java.util.Arrays;

import studio.engine.memory.MemoryGate;

/**
 * A map from long keys to non-negative int values with open addressing and no boxing, for
 * de-duplicating vertices by a pair of indices (OBJ position/normal pairs, icosphere edges).
 */
final class LongIntMap {

    private final MemoryGate memory;
    private long[] keys;
    private int[] values;
    private int size;

    LongIntMap(int expected) {
        this(expected, MemoryGate.UNLIMITED);
    }

    /** @param memory asked before the table is allocated and before it grows */
    LongIntMap(int expected, MemoryGate memory) {
        this.memory = memory;
        int capacity = Integer.highestOneBit(Math.max(16, expected * 2 - 1)) << 1;
        memory.reserve(MemoryGate.longs(capacity) + MemoryGate.ints(capacity));
        keys = new long[capacity];
        values = new int[capacity];
        Arrays.fill(values, -1);
    }

    /** The value for the key, or -1. */
    int get(long key) {
        int mask = keys.length - 1;
        for (int i = hash(key) & mask; ; i = (i + 1) & mask) {
            if (values[i] < 0) {
                return -1;
            }
            if (keys[i] == key) {
                return values[i];
            }
        }
    }

    /** Sets the value (at least 0) of a key not yet in the map. */
    void putNew(long key, int value) {
        if (2 * (size + 1) > keys.length) {
            grow();
        }
        int mask = keys.length - 1;
        int i = hash(key) & mask;
        while (values[i] >= 0) {
            i = (i + 1) & mask;
        }
        keys[i] = key;
        values[i] = value;
        size++;
    }

    private void grow() {
        long[] oldKeys = keys;
        int[] oldValues = values;
        memory.reserve(MemoryGate.longs(oldKeys.length * 2L) + MemoryGate.ints(oldKeys.length * 2L));
        keys = new long[oldKeys.length * 2];
        values = new int[oldValues.length * 2];
        Arrays.fill(values, -1);
        size = 0;
        for (int i = 0; i < oldKeys.length; i++) {
            if (oldValues[i] >= 0) {
                putNew(oldKeys[i], oldValues[i]);
            }
        }
    }

    /** MurmurHash3's 64-bit finaliser, so keys differing only in their high half spread too. */
    private static int hash(long key) {
        long h = key;
        h ^= h >>> 33;
        h *= 0xff51afd7ed558ccdL;
        h ^= h >>> 33;
        h *= 0xc4ceb9fe1a85ec53L;
        h ^= h >>> 33;
        return (int) h;
    }
}
