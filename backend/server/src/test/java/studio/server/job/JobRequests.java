package studio.server.job;

import studio.server.scene.compiling.CompiledScene;
import studio.server.system.IntakeMemory;

/** Job requests as tests submit them: a compiled scene, without a request's memory. */
public final class JobRequests {

    private JobRequests() {
    }

    /** A scene by anyone (sign-in off), without its JSON. */
    public static JobRequest of(CompiledScene scene) {
        return of(scene, null, JobOwner.ANYONE);
    }

    /** A scene by anyone, with the JSON it was compiled from (what a cluster's members read). */
    public static JobRequest of(CompiledScene scene, byte[] json) {
        return of(scene, json, JobOwner.ANYONE);
    }

    /** A scene by {@code owner}, with its JSON (null: none). */
    public static JobRequest of(CompiledScene scene, byte[] json, JobOwner owner) {
        return new JobRequest(scene, json, IntakeMemory.NONE, owner);
    }
}
