package studio.server.cluster;

/**
 * One tile of a job, as a task any member's worker may take.
 *
 * @param index   the tile's place in the job's tiling (row by row)
 * @param attempt 0 the first time; one more each time the tile failed or was lost with its member
 */
record TileTask(String jobId, int index, int attempt) {
}
