package studio.server.job;

import java.io.Serializable;

/**
 * An entry of a job's event log: a change of its state, or a finished tile. Serializable: in a
 * cluster the log is the cluster's too (see {@link JobCluster}).
 */
public sealed interface JobEvent extends Serializable permits JobStatus, TileEvent {
}
