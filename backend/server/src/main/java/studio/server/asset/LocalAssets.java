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
 *
 * <p>In a cluster, an asset uploaded here is also put into the cluster's copy ({@link SharedAssets}),
 * and one this member lacks is read from there, kept only if its bytes hash to its id, and then
 * kept here too.
 */
public final class LocalAssets implements AssetStore {

    private record Entry(Asset asset, MemoryBudget.Reservation memory) {
    }

    private final long capacity;
    private final MemoryBudget budget;
    private final Map<String, Entry> kept = new LinkedHashMap<>(16, 0.75f, true);
    private final SharedAssets shared;
    private long bytes;

    LocalAssets(long capacity, MemoryBudget budget) {
        this(capacity, budget, SharedAssets.NONE);
    }

    public LocalAssets(long capacity, MemoryBudget budget, SharedAssets shared) {
        this.capacity = capacity;
        this.budget = budget;
        this.shared = shared;
    }

    /** Keeps the asset here, then (outside this store's lock) puts it into the cluster's copy. */
    @Override
    public boolean put(Asset asset) {
        boolean added = keep(asset);
        shared.share(asset);
        return added;
    }

    /** Keeps the asset here only. */
    private synchronized boolean keep(Asset asset) {
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

    /** The asset kept here, else the cluster's copy's if its bytes hash to {@code id} (then kept here, if room). */
    @Override
    public Asset get(String id) {
        synchronized (this) {
            Entry entry = kept.get(id);
            if (entry != null) {
                return entry.asset();
            }
        }
        Asset found = shared.find(id);
        if (found == null || !AssetIds.of(found.bytes()).equals(id)) {
            return null;
        }
        try {
            keep(found);
        } catch (AssetRefusedException e) {
            // no room here now: used as it is, read from the cluster again next time
        }
        return found;
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
