package studio.server.cluster;

/**
 * A tile a worker rendered (its linear RGB, row by row, as the film holds it: the image is made
 * from these exact doubles, so it is the same bytes whichever member rendered the tile), or why it
 * could not.
 *
 * @param worker the member that rendered it ({@code host:port})
 * @param error  why the render failed, else null
 */
record TileResult(int index, int attempt, double[] rgb, long rays, long samples, long nonFinite, String worker,
                  String error) {

    static TileResult failed(TileTask task, String worker, String error) {
        return new TileResult(task.index(), task.attempt(), null, 0, 0, 0, worker, error);
    }

    boolean failed() {
        return error != null;
    }
}
