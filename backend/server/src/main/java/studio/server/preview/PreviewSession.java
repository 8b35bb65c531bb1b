package studio.server.preview;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;

import org.springframework.http.HttpStatus;
import org.springframework.web.ErrorResponseException;

import studio.engine.render.Film;
import studio.engine.render.RenderCancelledException;
import studio.engine.render.RenderSettings;
import studio.server.render.RenderTimeExceededException;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.format.InvalidSceneException;
import studio.server.system.IntakeMemory;
import studio.server.system.MemoryBudget;
import studio.server.system.MemoryBusyException;
import tools.jackson.databind.JsonNode;

/**
 * One live view: the revisions a client sent and the work of showing the newest. Messages only
 * join the pending ones and wake the view's worker (one task at a time on the shared worker pool),
 * which reads them in order (a patch applies to the revision before it, shown or not; a message
 * that gets a problem is answered), compiles the newest, then renders its passes coarse to fine
 * and sends a frame after each. Before each pass, and within each render (before every sample, as every render is
 * cancelled), the worker checks for a newer revision or a closed session and drops the old one's
 * work, except that the first, coarsest pass of a revision it has read is always shown. So
 * revisions that arrive faster than frames are skipped but the newest, a drag over a large scene
 * still shows a frame for every revision read, and frames go out in revision order: only the
 * worker sends.
 */
final class PreviewSession {

    /** Where frames and problems go (the WebSocket, or a test's recorder). */
    interface Output {
        void frame(byte[] message) throws IOException;

        void text(String message) throws IOException;

        /** Sending failed or the view is over: give the connection up. */
        void close();
    }

    /** A message as it arrived, with the memory its reading holds. */
    private record Message(byte[] message, IntakeMemory memory, long receivedNanos) {
    }

    /** The messages not yet read, oldest first. */
    private record Pending(List<Message> messages) {
        /** With the next message: after the others, or instead of them if it is a whole scene. */
        Pending with(Message next, boolean whole) {
            if (whole) {
                return new Pending(List.of(next));
            }
            List<Message> all = new ArrayList<>(messages.size() + 1);
            all.addAll(messages.size() < MAX_PENDING ? messages : messages.subList(1, messages.size()));
            all.add(next);
            return new Pending(List.copyOf(all));
        }
    }

    /**
     * Messages that wait to be read, at most: an older one is dropped for a newer (a patch against
     * it is then refused and the client sends the whole scene), and a whole scene drops every one
     * before it. The worker reads them all before a revision's passes, so only those of one read wait.
     */
    static final int MAX_PENDING = 32;

    /**
     * The passes of lattices this fine and finer render with the light buffers of the scene's final
     * pass ({@link PreviewRenderer#lit}); the coarser ones, a sixteenth of the pixels, do without.
     */
    static final int LIT_STEP = 2;

    private static final String BUSY = "the server is reading or rendering as much as its memory allows right now; the "
            + "view renders again with your next change";

    private final PreviewRenderer renderer;
    private final Executor worker;
    private final Output output;
    private final AtomicReference<Pending> pending = new AtomicReference<>();
    private final AtomicBoolean working = new AtomicBoolean();
    private volatile boolean closed;
    /**
     * A message has begun to arrive and is not yet whole: the revision being shown stops now, not
     * once the message is read, so that receiving it (a large scene takes tens of milliseconds)
     * does not share the cores with a render nobody will see.
     */
    private volatile boolean arriving;
    /** The last revision accepted (worker thread only). */
    private long lastRevision = -1;
    /** The last scene read, to read the next revision from where only some objects changed. */
    private final SceneReuse reuse;
    /** The scene the next patch applies to. */
    private final PatchBase patchBase;
    /** The one-sample film, kept to render only what the next edit can reach. */
    private final KeptFilm keptFilm;

    /** @param maxCopied what one patch's {@code copy} operations may copy in all (as a message's bytes are bounded) */
    PreviewSession(PreviewRenderer renderer, Executor worker, Output output, long maxCopied) {
        this.renderer = renderer;
        this.worker = worker;
        this.output = output;
        this.reuse = new SceneReuse(renderer.memory());
        this.patchBase = new PatchBase(renderer.memory(), maxCopied);
        this.keptFilm = new KeptFilm(renderer.memory());
    }

    /**
     * The first piece of a message has arrived: the revision being shown stops (within a tile),
     * as it would once the message is whole; every new message, valid or not, ends it.
     */
    void arriving() {
        arriving = true;
    }

    /** The message begun by {@link #arriving} was dropped (refused while it arrived) before it was whole. */
    void notArriving() {
        arriving = false;
    }

    /** A message from the client: it joins those not yet read, and stops the revision being shown. */
    void receive(byte[] message, IntakeMemory memory) {
        Message next = new Message(message, memory, System.nanoTime());
        boolean whole = PreviewRequest.isWholeScene(message);
        Pending before = pending.getAndUpdate(p -> p == null ? new Pending(List.of(next)) : p.with(next, whole));
        arriving = false;
        if (before != null) {
            // what the update dropped for the newer gives its memory back: all before a whole scene, else the oldest of a full list
            List<Message> dropped = whole ? before.messages()
                    : before.messages().size() == MAX_PENDING ? before.messages().subList(0, 1) : List.of();
            dropped.forEach(m -> m.memory().close());
        }
        wake();
    }

    /** The client went away: the work in hand stops within a tile. */
    void close() {
        closed = true;
        reuse.close();
        patchBase.close();
        keptFilm.close();
        Pending dropped = pending.getAndSet(null);
        if (dropped != null) {
            dropped.messages().forEach(m -> m.memory().close());
        }
    }

    boolean closed() {
        return closed;
    }

    private void wake() {
        if (working.compareAndSet(false, true)) {
            try {
                worker.execute(this::work);
            } catch (RejectedExecutionException e) {
                working.set(false);
                output.close(); // the server is stopping
            }
        }
    }

    private void work() {
        for (;;) {
            Pending next = closed ? null : pending.getAndSet(null);
            if (next == null) {
                working.set(false);
                // a message that arrived after getAndSet found the worker busy: look once more
                if (closed || pending.get() == null || !working.compareAndSet(false, true)) {
                    return;
                }
                continue;
            }
            try {
                show(next.messages());
            } catch (IOException | RuntimeException e) {
                closed = true;
                output.close();
                return;
            } finally {
                next.messages().forEach(m -> m.memory().close());
            }
        }
    }

    /** Whether the revision being shown is no longer wanted: the view closed, or a newer message arrived or is arriving. */
    private boolean superseded() {
        return closed || arriving || pending.get() != null;
    }

    /**
     * The kept film the revision's one-sample passes render into, only where the edit since the
     * last revision reaches; null (they render into a film of their own) when the last of them is
     * the final frame, which is always rendered afresh, or when the memory cannot hold it.
     */
    private KeptFilm.Kept keptFilmFor(SceneReuse.Revision revision, List<PreviewPass> passes) {
        RenderSettings oneSample = passes.get(0).settings();
        if (passes.get(passes.size() - 1).settings().equals(oneSample)) {
            keptFilm.drop();
            return null;
        }
        return keptFilm.prepare(revision.compiled().scene(), oneSample, revision.origins());
    }

    /**
     * Reads the messages in order, answering each that gets a problem, and compiles the newest
     * revision that reads; null if none does.
     */
    private Read read(List<Message> messages) throws IOException {
        Read newest = null;
        for (Message message : messages) {
            try {
                PreviewRequest request = PreviewRequest.parse(message.message(), renderer.limits().maxWidth(),
                        renderer.limits().maxHeight());
                if (request.revision() <= lastRevision) {
                    throw new InvalidSceneException("revision", "must be greater than the last revision, " + lastRevision);
                }
                lastRevision = request.revision();
                if (request.patch() == null) {
                    patchBase.whole(request.revision(), request.scene());
                    newest = new Read(request, message, null);
                } else {
                    newest = new Read(request, message, patchBase.patch(request.revision(), request.base(), request.patch()));
                }
            } catch (ErrorResponseException e) {
                // an invalid message or patch: no patch applies until the next whole scene
                patchBase.forget();
                newest = null;
                output.text(renderer.problem(PreviewRequest.revisionOf(message.message()), e));
            }
        }
        return newest;
    }

    /** A revision read: its message, and its scene's tree if it was patched. */
    private record Read(PreviewRequest request, Message message, JsonNode patched) {
    }

    private void show(List<Message> messages) throws IOException {
        Read read = read(messages);
        if (read == null) {
            return;
        }
        PreviewRequest request = read.request();
        Message next = read.message();
        SceneReuse.Revision revision;
        try {
            revision = read.patched() == null ? renderer.compile(request, next.memory(), reuse)
                    : renderer.compilePatched(request, patchBase.compiledTree(), read.patched(), patchBase.origins(),
                    next.memory(), reuse);
            patchBase.compiled();
        } catch (ErrorResponseException e) {
            // an invalid scene (400), the memory to build it is taken right now (503), or it could never
            // fit (413): no patch applies until the next whole scene
            patchBase.forget();
            output.text(renderer.problem(request.revision(), e));
            return;
        } finally {
            next.memory().close(); // the passes reserve their own render memory, which counts the scene
        }
        CompiledScene scene = revision.compiled();
        List<PreviewPass> passes = PreviewPass.plan(scene.settings());
        KeptFilm.Kept kept = keptFilmFor(revision, passes);
        Film film = null;
        MemoryBudget.Reservation passMemory = null;
        // with the light buffers its final pass pays for, from the first pass of a quarter of the pixels on
        CompiledScene lit = null;
        try {
            for (PreviewPass pass : passes) {
                // the first, coarsest pass is shown even if a newer revision is waiting: it costs little
                // next to reading the scene, and in a drag over a scene that takes longer to read than
                // the drag's steps, every revision would otherwise be dropped unseen until the drag stops
                boolean first = pass.number() == 1;
                if (!first && superseded()) {
                    return;
                }
                boolean intoKept = kept != null && !pass.last();
                byte[] frame;
                try {
                    if (first || pass.except() == null) {
                        // the mosaic's passes, then the target's: their memory first
                        if (passMemory != null) {
                            passMemory.close();
                        }
                        passMemory = renderer.reserve(scene, pass.settings());
                        if (passMemory == null) {
                            output.text(renderer.problem(request.revision(), HttpStatus.SERVICE_UNAVAILABLE,
                                    "Service Unavailable", BUSY));
                            return;
                        }
                        film = intoKept ? kept.film() : new Film(pass.settings().width(), pass.settings().height());
                    }
                    if (lit == null && pass.pixels().step() <= LIT_STEP) {
                        lit = renderer.lit(scene, passMemory);
                        reuse.lit(scene, lit);
                    }
                    frame = renderer.render(lit != null ? lit : scene, pass, film, intoKept ? kept.paths() : null,
                            request.revision(), next.receivedNanos(), first ? this::closed : this::superseded);
                } catch (RenderCancelledException e) {
                    return;
                } catch (RenderTimeExceededException | InvalidSceneException | MemoryBusyException e) {
                    // past the render time budget (422), it could never fit the render memory (400), or it is
                    // taken right now (503)
                    output.text(renderer.problem(request.revision(), e));
                    return;
                }
                output.frame(frame);
            }
        } finally {
            if (passMemory != null) {
                passMemory.close();
            }
        }
    }
}
