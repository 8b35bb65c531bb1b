package studio.server.cluster;

/**
 * The names of the cluster's data structures. Every value in them is sealed bytes ({@link ClusterData}). Each is kept with one backup on another member
 * (Hazelcast's default, set explicitly in {@link MemberConfig}), so the loss of any one member
 * loses none of it.
 */
final class ClusterMaps {

    /** Job id to {@link JobRecord}: the job table every member serves from. */
    static final String JOBS = "studio-jobs";
    /** Job id to the scene's JSON, meshes inline: what a member compiles once per job. */
    static final String SCENES = "studio-scenes";
    /** Asset id to the asset (its media type and bytes): the assets uploaded to any member. */
    static final String ASSETS = "studio-assets";
    /** Job id to the finished image's bytes. */
    static final String IMAGES = "studio-images";
    /** Job id to the reason of a cancel asked for through a member that does not run the job. */
    static final String CANCELS = "studio-cancels";
    /** Job id to when a client last asked about it through another member (epoch millis). */
    static final String SEEN = "studio-seen";
    /**
     * How jobs are cut into tiles ({@link ClusterTiling}), named in the structures that hold tiles by
     * number: the queue, the results and the claims. Members of builds that cut a job differently
     * then share no tile (a tile number is another rectangle to each): during a rolling restart onto
     * another tiling each build renders its own owners' jobs, and a job handed from one build to the
     * other renders its tiles again. Named structures before this carried no tiling (uniform tiles).
     */
    static final String TILING = "t2";
    /** The {@link TileTask}s every member's workers take from, all jobs' in the order queued. */
    static final String TILE_QUEUE = "studio-tile-queue-" + TILING;

    /** The families of the per-job structures: their sealing keys and rejection counters. */
    static final String TILES_FAMILY = "studio-tiles", CLAIMS_FAMILY = "studio-claims";

    private static final String TILES = TILES_FAMILY + "-" + TILING + "-";
    private static final String CLAIMS = CLAIMS_FAMILY + "-" + TILING + "-";
    private static final String EVENTS = "studio-events-";

    private ClusterMaps() {
    }

    /** Tile index to {@link TileResult}: the job's finished tiles. */
    static String tiles(String jobId) {
        return TILES + jobId;
    }

    /** Tile index to {@link TileClaim}: the tiles a worker has taken and not finished yet. */
    static String claims(String jobId) {
        return CLAIMS + jobId;
    }

    /** The ring buffer of the job's {@link studio.server.job.JobEvent}s: its event log, cluster-wide. */
    static String events(String jobId) {
        return EVENTS + jobId;
    }

    /** Every tiling's result maps: a job's maps left by a member of another tiling expire as this one's do. */
    static String tilesPattern() {
        return TILES_FAMILY + "-*";
    }

    /** Every tiling's claim maps, as {@link #tilesPattern()}. */
    static String claimsPattern() {
        return CLAIMS_FAMILY + "-*";
    }

    static String eventsPattern() {
        return EVENTS + "*";
    }
}
