package studio.engine.render;

import studio.engine.sampler.PixelSamples;

/** Every pixel takes all of the sampler's samples: one pattern of them. */
final class FixedSampling implements TileSampling {

    private final SampleTracer tracer;
    private final PixelSamples pixelSamples;
    private final double[] xs, ys;
    private long samples;

    FixedSampling(RenderSettings settings, SampleTracer tracer) {
        this.tracer = tracer;
        int n = settings.sampler().samplesPerPixel();
        pixelSamples = new PixelSamples(settings.sampler(), n, settings.seed());
        xs = new double[n];
        ys = new double[n];
    }

    @Override
    public long render(TileRequest request) {
        Film film = request.film();
        TileRect tile = request.tile();
        PixelLattice pixels = request.pixels(), except = request.except();
        PixelPaths paths = request.paths();
        long bad = 0;
        int step = pixels.step(), n = pixelSamples.samplesPerPixel();
        for (int y = pixels.first(tile.y()); y < tile.y() + tile.height(); y += step) {
            for (int x = pixels.first(tile.x()); x < tile.x() + tile.width(); x += step) {
                if (except != null && except.contains(x, y) || paths != null && paths.known(x, y)) {
                    continue;
                }
                pixelSamples.startPixel(x, y);
                pixelSamples.fill(0, n, xs, ys);
                int p = paths == null ? 0 : paths.index(x, y);
                if (paths != null) {
                    paths.start(p);
                }
                tracer.recordInto(paths, p);
                bad += tracer.trace(x, y, xs, ys, 0, n);
                samples += n;
                film.set(x, y, tracer.sumR / n, tracer.sumG / n, tracer.sumB / n);
                if (paths != null) {
                    paths.finish(p);
                }
            }
        }
        return bad;
    }

    @Override
    public long samples() {
        return samples;
    }
}
