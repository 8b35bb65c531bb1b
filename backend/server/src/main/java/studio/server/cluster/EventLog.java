package studio.server.cluster;

import java.io.IOException;
import java.util.HashSet;
import java.util.Set;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.TimeUnit;

import com.hazelcast.nio.serialization.HazelcastSerializationException;
import com.hazelcast.ringbuffer.ReadResultSet;
import com.hazelcast.ringbuffer.Ringbuffer;

import studio.server.job.JobEvent;
import studio.server.job.TileEvent;

/**
 * A job's event log in the cluster: a ring buffer of sealed {@link JobEvent}s (see {@link SealedMap};
 * the associated data is the ring buffer's name, so an event opens only in its own job's log). An
 * event that does not open reads as null, and is skipped by its readers.
 */
final class EventLog {

    static final String FAMILY = "studio-events";

    private final Ringbuffer<byte[]> events;
    private final Seal seal;

    EventLog(Ringbuffer<byte[]> events, Seal seal) {
        this.events = events;
        this.seal = seal;
    }

    String name() {
        return events.getName();
    }

    void add(JobEvent event) {
        events.add(seal.seal(FAMILY, events.getName(), "", ClusterCodecs.EVENT.encode(event)));
    }

    long headSequence() {
        return events.headSequence();
    }

    long tailSequence() {
        return events.tailSequence();
    }

    CompletionStage<ReadResultSet<byte[]>> readMany(long from, int min, int max) {
        return events.readManyAsync(from, min, max, null);
    }

    /** The event of the batch's {@code i}th entry, or null if it is not one that opens (counted). */
    JobEvent open(ReadResultSet<byte[]> batch, int i) {
        Object value;
        try {
            value = ((ReadResultSet<?>) batch).get(i);
        } catch (HazelcastSerializationException e) {
            seal.reject(FAMILY, events.getName(), "it does not deserialize: " + e.getMessage());
            return null;
        }
        if (!(value instanceof byte[] sealed)) {
            seal.reject(FAMILY, events.getName(), "it is not bytes");
            return null;
        }
        return open(sealed);
    }

    /** The event of a sealed entry read from the log, or null if it does not open (counted). */
    JobEvent open(byte[] sealed) {
        byte[] plain = seal.open(FAMILY, events.getName(), "", sealed);
        if (plain == null) {
            return null;
        }
        try {
            return ClusterCodecs.EVENT.decode(plain);
        } catch (IOException | RuntimeException e) {
            seal.reject(FAMILY, events.getName(), "it does not decode: " + e.getMessage());
            return null;
        }
    }

    void destroy() {
        events.destroy();
    }

    /** The tiles whose events a job's ring buffer holds. */
    Set<String> publishedTiles(long timeoutSeconds) {
        Set<String> tiles = new HashSet<>();
        long next = headSequence(), tail = tailSequence();
        while (next <= tail) {
            ReadResultSet<byte[]> batch = readMany(next, 0, 1000).toCompletableFuture()
                    .orTimeout(timeoutSeconds, TimeUnit.SECONDS).join();
            if (batch.size() == 0) {
                break;
            }
            for (int i = 0; i < batch.size(); i++) {
                if (open(batch, i) instanceof TileEvent tile) {
                    tiles.add(JobPublisher.key(tile));
                }
            }
            next = batch.getNextSequenceToReadFrom();
        }
        return tiles;
    }
}
