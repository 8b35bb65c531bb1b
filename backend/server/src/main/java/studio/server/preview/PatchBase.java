package studio.server.preview;

import java.util.concurrent.atomic.AtomicReference;

import studio.server.preview.patch.JsonPatch;
import studio.server.preview.patch.PatchException;
import studio.server.scene.format.InvalidSceneException;
import studio.server.system.IntakeMemory;
import studio.server.system.MemoryBudget;
import tools.jackson.core.JacksonException;
import tools.jackson.core.StreamReadFeature;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.cfg.JsonNodeFeature;
import tools.jackson.databind.json.JsonMapper;

/**
 * The scene a live view's next patch applies to: that of the last revision the view read (whole
 * or patched), as its bytes until a patch comes and then as a Jackson tree, with numbers kept as
 * written ({@code BigDecimal}s), so that a patched scene reads as its whole JSON would. Also the
 * tree of the last revision compiled and the {@link ObjectOrigins} of the patches applied since,
 * which tell {@link SceneReuse} and the kept film what changed.
 *
 * <p>Any revision that gets a problem forgets the base: a patch against it, or against any revision
 * but the last one read, is refused and the client sends the whole scene. The base is held in the
 * render memory while the view is open, as a yielding reservation: when other work needs the
 * memory it is dropped, and the next patch is refused the same way. Used by the view's worker,
 * one message at a time; {@link #close} by any thread.
 */
final class PatchBase implements AutoCloseable {

    /** Reads patches and bases: duplicate members refused, numbers as written. */
    static final JsonMapper TREES = JsonMapper.builder()
            .enable(StreamReadFeature.STRICT_DUPLICATE_DETECTION)
            .enable(JsonNodeFeature.USE_BIG_DECIMAL_FOR_FLOATS)
            .disable(JsonNodeFeature.STRIP_TRAILING_BIGDECIMAL_ZEROES)
            .build();

    /** The base: its revision, its bytes (until it is read as a tree), its tree, and their memory. */
    private record Base(long revision, byte[] json, JsonNode tree, long bytes, MemoryBudget.Reservation memory) {
    }

    private final MemoryBudget memory;
    private final long maxCopied;
    private final AtomicReference<Base> base = new AtomicReference<>();
    private volatile boolean closed;
    /** Whether the base is the revision compiled last (then the next patch starts a new tally). */
    private boolean baseCompiled;
    /** The tree of the revision compiled last, once a patch has applied to it, and the tally of patches since. */
    private JsonNode compiledTree;
    private ObjectOrigins origins;

    /** @param maxCopied what a patch's {@code copy} operations may copy in all (see {@link JsonPatch#applyTo}) */
    PatchBase(MemoryBudget memory, long maxCopied) {
        this.memory = memory;
        this.maxCopied = maxCopied;
    }

    /** A whole scene was read as revision {@code revision}: it is the base now. */
    void whole(long revision, byte[] json) {
        hold(revision, json, null, json.length);
        baseCompiled = false;
        compiledTree = null;
        origins = null;
    }

    /**
     * The base with a patch applied: the base from now on.
     *
     * @throws InvalidSceneException naming {@code base} when it is not the base's revision, or the
     *         patch's operation that does not apply
     */
    JsonNode patch(long revision, long against, JsonPatch patch) {
        Base from = base.get();
        if (from == null || from.revision() != against) {
            throw new InvalidSceneException("base", "is not the revision this view has last read"
                    + (from == null ? "" : " (" + from.revision() + ")") + "; send the whole scene");
        }
        JsonNode tree;
        try {
            tree = from.tree() != null ? from.tree() : TREES.readTree(from.json());
        } catch (JacksonException e) {
            throw new InvalidSceneException("base", "the scene of revision " + against + " does not read ("
                    + e.getOriginalMessage() + "); send the whole scene");
        }
        // what the tree takes, reckoned once from its JSON as a request body's parse is
        long bytes = from.tree() != null ? from.bytes() : treeBytes(from.json());
        JsonNode patched;
        try {
            patched = patch.applyTo(tree, maxCopied);
        } catch (PatchException e) {
            throw new InvalidSceneException(e.field(), e.getMessage());
        }
        if (baseCompiled) {
            compiledTree = tree;
            JsonNode objects = tree.get("objects");
            origins = new ObjectOrigins(objects != null && objects.isArray() ? objects.size() : 0);
            baseCompiled = false;
        }
        if (origins != null) {
            origins.follow(patch);
        }
        hold(revision, null, patched, bytes);
        return patched;
    }

    /** The base's revision was compiled: patches from now on are tallied against it. */
    void compiled() {
        baseCompiled = true;
        compiledTree = null;
        origins = null;
    }

    /** The tree of the revision compiled last (null if no patch has applied since a whole scene). */
    JsonNode compiledTree() {
        return compiledTree;
    }

    /** What the patches since the revision compiled last changed; null if not known. */
    ObjectOrigins origins() {
        return origins;
    }

    /** A revision got a problem: no patch applies until the next whole scene. */
    void forget() {
        release();
        baseCompiled = false;
        compiledTree = null;
        origins = null;
    }

    @Override
    public void close() {
        closed = true;
        release();
    }

    private static long treeBytes(byte[] json) {
        try (IntakeMemory reckoning = IntakeMemory.of(MemoryBudget.unlimited())) {
            reckoning.bodyArrived(json, 0, json.length);
            return reckoning.bytes();
        }
    }

    private void hold(long revision, byte[] json, JsonNode tree, long bytes) {
        release();
        if (closed) {
            return;
        }
        MemoryBudget.Reservation reservation = memory.tryReserveYielding(bytes, this::release);
        if (reservation != null) {
            base.set(new Base(revision, json, tree, bytes, reservation));
            if (closed) {
                release();
            }
        }
    }

    private void release() {
        Base dropped = base.getAndSet(null);
        if (dropped != null) {
            dropped.memory().close();
        }
    }
}
