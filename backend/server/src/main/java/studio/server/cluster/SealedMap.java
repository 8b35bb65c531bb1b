package studio.server.cluster;

import java.io.IOException;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.TimeUnit;
import java.util.function.BiConsumer;
import java.util.function.Supplier;
import java.util.function.UnaryOperator;

import com.hazelcast.core.EntryEvent;
import com.hazelcast.map.IMap;
import com.hazelcast.map.listener.EntryAddedListener;
import com.hazelcast.map.listener.EntryUpdatedListener;
import com.hazelcast.nio.serialization.HazelcastSerializationException;

/**
 * A cluster map whose values are sealed bytes ({@link Seal}), seen as values of one type: each
 * value is encoded by its {@link Codec} and sealed with the map's name and the entry's key as
 * associated data; a value that does not open or decode reads as absent (and is counted).
 * Keys are Strings or Integers, which Hazelcast writes without Java serialization.
 */
final class SealedMap<K, V> {

    /** A job's status is written at most this many times over one read (other members write it too). */
    static final int UPDATE_TRIES = 16;

    private final IMap<K, byte[]> map;
    /** The same map, read: values of other types than byte[] may be found in it, and are checked. */
    private final IMap<K, Object> read;
    private final String family;
    private final Codec<V> codec;
    private final Seal seal;

    @SuppressWarnings({"unchecked", "rawtypes"})
    SealedMap(IMap<K, byte[]> map, String family, Codec<V> codec, Seal seal) {
        this.map = map;
        this.read = (IMap) map;
        this.family = family;
        this.codec = codec;
        this.seal = seal;
    }

    String name() {
        return map.getName();
    }

    V get(K key) {
        return open(key, () -> read.get(key));
    }

    boolean containsKey(K key) {
        return map.containsKey(key);
    }

    void set(K key, V value) {
        map.set(key, seal(key, value));
    }

    void set(K key, V value, long ttl, TimeUnit unit) {
        map.set(key, seal(key, value), ttl, unit);
    }

    CompletionStage<Void> setAsync(K key, V value) {
        return map.setAsync(key, seal(key, value));
    }

    void delete(K key) {
        map.delete(key);
    }

    CompletionStage<Boolean> deleteAsync(K key) {
        return map.deleteAsync(key);
    }

    boolean remove(K key, V expected) {
        byte[] now = bytes(key, () -> read.get(key));
        V value = open(key, now);
        return value != null && value.equals(expected) && map.remove(key, now);
    }

    Set<K> keySet() {
        return map.keySet();
    }

    /** The entries that open, in no particular order. */
    Map<K, V> entries() {
        Map<K, V> entries = new LinkedHashMap<>();
        try {
            for (Map.Entry<K, Object> entry : read.entrySet()) { // deserialized lazily, as it is iterated
                V value = open(entry.getKey(), entry::getValue);
                if (value != null) {
                    entries.put(entry.getKey(), value);
                }
            }
        } catch (HazelcastSerializationException e) {
            // some value is not bytes (Java-serialized, refused): read them all one by one
            entries.clear();
            for (K key : map.keySet()) {
                V value = get(key);
                if (value != null) {
                    entries.put(key, value);
                }
            }
        }
        return entries;
    }

    Collection<V> values() {
        return entries().values();
    }

    Map<K, V> getAll(Set<K> keys) {
        Map<K, V> entries = new LinkedHashMap<>();
        for (K key : keys) {
            V value = get(key);
            if (value != null) {
                entries.put(key, value);
            }
        }
        return entries;
    }

    /**
     * Changes an entry by compare-and-set: reads it, asks {@code change} for the next value (null:
     * leave it), and writes that only if the entry is still what was read; tries again if it was not,
     * at most {@value #UPDATE_TRIES} times.
     *
     * @return true if the change was written
     */
    boolean update(K key, UnaryOperator<V> change) {
        for (int i = 0; i < UPDATE_TRIES; i++) {
            byte[] before = bytes(key, () -> read.get(key));
            V value = open(key, before);
            if (value == null) {
                return false;
            }
            V next = change.apply(value);
            if (next == null) {
                return false;
            }
            if (map.replace(key, before, seal(key, next))) {
                return true;
            }
        }
        return false;
    }

    /** Calls {@code listener} (on a Hazelcast event thread) with each value added or replaced that opens. */
    UUID listen(BiConsumer<K, V> listener) {
        return map.addEntryListener(new Listener<>(this, listener), true);
    }

    void removeListener(UUID registration) {
        map.removeEntryListener(registration);
    }

    void destroy() {
        map.destroy();
    }

    byte[] seal(K key, V value) {
        return seal.seal(family, map.getName(), key, codec.encode(value));
    }

    /** The value read, or null if it is not sealed bytes that open and decode (then counted as rejected). */
    V open(K key, Supplier<Object> read) {
        return open(key, bytes(key, read));
    }

    /**
     * The bytes read, or null if there are none, or the value is not bytes: one Hazelcast wrote by
     * another serializer (a Date, say), or a Java-serialized one, which the filter refuses to read
     * ({@link MemberConfig}); both counted as rejected.
     */
    private byte[] bytes(K key, Supplier<Object> read) {
        Object value;
        try {
            value = read.get();
        } catch (HazelcastSerializationException e) {
            seal.reject(family, map.getName(), "it does not deserialize: " + e.getMessage());
            return null;
        }
        if (value == null || value instanceof byte[]) {
            return (byte[]) value;
        }
        seal.reject(family, map.getName(), "it is not bytes but a " + value.getClass().getName());
        return null;
    }

    /** The value of sealed bytes, or null if they do not open or decode (then counted as rejected). */
    V open(K key, byte[] sealed) {
        byte[] plain = seal.open(family, map.getName(), key, sealed);
        if (plain == null) {
            return null;
        }
        try {
            return codec.decode(plain);
        } catch (IOException | RuntimeException e) {
            seal.reject(family, map.getName(), "it does not decode: " + e.getMessage());
            return null;
        }
    }

    private record Listener<K, V>(SealedMap<K, V> map, BiConsumer<K, V> listener)
            implements EntryAddedListener<K, byte[]>, EntryUpdatedListener<K, byte[]> {

        @Override
        public void entryAdded(EntryEvent<K, byte[]> event) {
            deliver(event);
        }

        @Override
        public void entryUpdated(EntryEvent<K, byte[]> event) {
            deliver(event);
        }

        private void deliver(EntryEvent<K, byte[]> event) {
            V value = map.open(event.getKey(), () -> ((EntryEvent<K, ?>) event).getValue());
            if (value != null) {
                listener.accept(event.getKey(), value);
            }
        }
    }
}
