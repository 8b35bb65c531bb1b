package studio.server.cluster;

import java.util.LinkedHashMap;
import java.util.Map;

import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.system.IntakeMemory;
import studio.server.system.MemoryBudget;

/**
 * The scenes of the jobs this member's workers render, compiled once per job per member from the
 * JSON in the cluster's scene map (the JSON travels once per job to each member, not once per tile;
 * a job of this member's own brings its scene already compiled). The compile draws on the memory
 * budget, and the scene keeps its memory until it is forgotten: when its job ends, or when more
 * than {@value #KEPT} jobs are being rendered at once (least recently used first).
 */
final class JobScenes {

    static final int KEPT = 4;

    private record Entry(CompiledScene scene, IntakeMemory memory) {
    }

    private final SealedMap<String, byte[]> json;
    private final SceneCompiler compiler;
    private final MemoryBudget memory;
    private final Map<String, Entry> scenes = new LinkedHashMap<>(8, 0.75f, true);

    JobScenes(SealedMap<String, byte[]> json, SceneCompiler compiler, MemoryBudget memory) {
        this.json = json;
        this.compiler = compiler;
        this.memory = memory;
    }

    /** A scene this member compiled already (its job's own), kept without memory of its own. */
    synchronized void offer(String jobId, CompiledScene scene) {
        put(jobId, new Entry(scene, IntakeMemory.NONE));
    }

    /**
     * The job's scene, compiled here on first use (outside this object's lock: compiling a mesh
     * scene takes a while).
     *
     * @return null if the cluster has no scene for the job (it ended and was forgotten)
     * @throws studio.server.system.MemoryBusyException if the budget cannot hold the scene now
     */
    CompiledScene scene(String jobId) {
        synchronized (this) {
            Entry entry = scenes.get(jobId);
            if (entry != null) {
                return entry.scene();
            }
        }
        byte[] bytes = json.get(jobId);
        if (bytes == null) {
            return null;
        }
        IntakeMemory held = IntakeMemory.of(memory);
        CompiledScene compiled;
        try {
            compiled = compiler.compile(CompileRequest.of(bytes).within(held));
        } catch (RuntimeException e) {
            held.close();
            throw e;
        }
        synchronized (this) {
            Entry entry = scenes.get(jobId);
            if (entry != null) { // another worker compiled it meanwhile
                held.close();
                return entry.scene();
            }
            put(jobId, new Entry(compiled, held));
        }
        return compiled;
    }

    synchronized void forget(String jobId) {
        Entry entry = scenes.remove(jobId);
        if (entry != null) {
            entry.memory().close();
        }
    }

    private void put(String jobId, Entry entry) {
        scenes.put(jobId, entry);
        while (scenes.size() > KEPT) {
            String eldest = scenes.keySet().iterator().next();
            scenes.remove(eldest).memory().close();
        }
    }
}
