package studio.server.job;

import studio.server.scene.compiling.CompiledScene;
import studio.server.system.IntakeMemory;

/**
 * A validated scene to queue as a job.
 *
 * @param scene     the compiled scene
 * @param sceneJson the JSON it was compiled from (null: none); in a cluster it travels to the members
 *                  that render the job's tiles
 * @param intake    the request's memory, which hands over to the job's
 * @param owner     who submits it: only they see the job, within their limit
 */
public record JobRequest(CompiledScene scene, byte[] sceneJson, IntakeMemory intake, JobOwner owner) {
}
