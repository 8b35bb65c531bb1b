package studio.server.job;

/** An entry of a job's event log: a change of its state, or a finished tile. */
sealed interface JobEvent permits JobStatus, TileEvent {
}
