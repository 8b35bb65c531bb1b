package studio.server.asset;

import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;

import studio.server.system.MemoryBudget;

/**
 * Assets in this member's memory, up to {@code capacity} bytes, each holding its bytes' share of the
 * service's {@link MemoryBudget} while it is kept. To make room, the least recently used assets are
 * dropped first (a scene compiled from one, or a GET of it, uses it). Dropping one never breaks
 * work under way: a render, job or live view renders the meshes compiled from an asset's bytes, not
 * the bytes; a scene sent after the drop is refused with the asset's id, for the client to upload
 * it again. When even an empty store cannot reserve the memory (renders hold it), the upload is
 * refused with 503 and Retry-After.
 */
final class LocalAssets implements AssetStore {

    private record Entry(Asset asset, MemoryBudget.Reservation memory) {
    }

    private final long capacity;
    private final MemoryBudget budget;
    private final Map<String, Entry> kept = new LinkedHashMap<>(16, 0.75f, true);
    private long bytes;

    LocalAssets(long capacity, MemoryBudget budget) {
        this.capacity = capacity;
        this.budget = budget;
    }

    @Override
    public synchronized boolean put(Asset asset) {
        if (kept.get(asset.id()) != null) {
            return false;
        }
        long size = asset.bytes().length;
        if (size > capacity) {
            throw AssetRefusedException.tooLarge(size, capacity);
        }
        while (bytes + size > capacity && dropOldest()) {
            // dropping
        }
        MemoryBudget.Reservation memory;
        while ((memory = budget.tryReserve(size)) == null) {
            if (!dropOldest()) {
                throw AssetRefusedException.full(size);
            }
        }
        kept.put(asset.id(), new Entry(asset, memory));
        bytes += size;
        return true;
    }

    @Override
    public synchronized Asset get(String id) {
        Entry entry = kept.get(id);
        return entry != null ? entry.asset() : null;
    }

    @Override
    public synchronized boolean contains(String id) {
        return kept.containsKey(id);
    }

    /** Bytes kept now. */
    synchronized long bytes() {
        return bytes;
    }

    private boolean dropOldest() {
        Iterator<Entry> oldest = kept.values().iterator();
        if (!oldest.hasNext()) {
            return false;
        }
        Entry entry = oldest.next();
        oldest.remove();
        bytes -= entry.asset().bytes().length;
        entry.memory().close();
        return true;
    }
}
