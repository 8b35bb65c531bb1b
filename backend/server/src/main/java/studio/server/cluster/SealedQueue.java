package studio.server.cluster;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.concurrent.TimeUnit;

import com.hazelcast.collection.IQueue;
import com.hazelcast.nio.serialization.HazelcastSerializationException;

/**
 * A cluster queue of sealed values (see {@link SealedMap}); the associated data is the queue's name.
 * A value that does not open is dropped as it is taken.
 */
final class SealedQueue<V> {

    private final IQueue<byte[]> queue;
    /** The same queue, read: a value of another type than byte[] is dropped. */
    private final IQueue<Object> read;
    private final String family;
    private final Codec<V> codec;
    private final Seal seal;

    @SuppressWarnings({"unchecked", "rawtypes"})
    SealedQueue(IQueue<byte[]> queue, String family, Codec<V> codec, Seal seal) {
        this.queue = queue;
        this.read = (IQueue) queue;
        this.family = family;
        this.codec = codec;
        this.seal = seal;
    }

    boolean offer(V value) {
        return queue.offer(seal(value));
    }

    void add(V value) {
        queue.add(seal(value));
    }

    void addAll(Collection<V> values) {
        if (values.isEmpty()) {
            return;
        }
        List<byte[]> sealed = new ArrayList<>(values.size());
        for (V value : values) {
            sealed.add(seal(value));
        }
        queue.addAll(sealed);
    }

    /**
     * The next value that opens, waiting at most {@code timeout} in all; values that do not open are
     * dropped on the way.
     */
    V poll(long timeout, TimeUnit unit) throws InterruptedException {
        long deadline = System.nanoTime() + unit.toNanos(timeout);
        while (true) {
            Object sealed;
            try {
                sealed = read.poll(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            } catch (HazelcastSerializationException e) {
                seal.reject(family, queue.getName(), "it does not deserialize: " + e.getMessage());
                continue;
            }
            if (sealed == null) {
                return null;
            }
            V value = open(sealed);
            if (value != null || System.nanoTime() - deadline > 0) {
                return value;
            }
        }
    }

    /** The values in the queue now, those that open. */
    List<V> snapshot() {
        List<V> values = new ArrayList<>();
        Object[] all;
        try {
            all = read.toArray();
        } catch (HazelcastSerializationException e) {
            seal.reject(family, queue.getName(), "it does not deserialize: " + e.getMessage());
            return values;
        }
        for (Object sealed : all) {
            V value = open(sealed);
            if (value != null) {
                values.add(value);
            }
        }
        return values;
    }

    void destroy() {
        queue.destroy();
    }

    private byte[] seal(V value) {
        return seal.seal(family, queue.getName(), "", codec.encode(value));
    }

    private V open(Object value) {
        if (!(value instanceof byte[] sealed)) {
            seal.reject(family, queue.getName(), "it is not bytes");
            return null;
        }
        byte[] plain = seal.open(family, queue.getName(), "", sealed);
        if (plain == null) {
            return null;
        }
        try {
            return codec.decode(plain);
        } catch (IOException | RuntimeException e) {
            seal.reject(family, queue.getName(), "it does not decode: " + e.getMessage());
            return null;
        }
    }
}
