package studio.server.job;

/**
 * An entry of a job's event log: a change of its state, or a finished tile. In a cluster the log
 * is the cluster's too (see {@link JobCluster}), written by an explicit codec.
 */
public sealed interface JobEvent permits JobStatus, TileEvent {
}
