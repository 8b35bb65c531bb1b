package studio.engine.render;

import studio.engine.sampler.PixelRandom;
import studio.engine.sampler.Sampler;

/** Every pixel takes all of the sampler's samples, one pattern drawn from the pixel's random stream. */
final class FixedSampling implements TileSampling {

    private final SampleTracer tracer;
    private final Sampler sampler;
    private final PixelRandom random = new PixelRandom();
    private final double[] xs, ys;
    private final long seed;
    private long samples;

    FixedSampling(RenderSettings settings, SampleTracer tracer) {
        this.tracer = tracer;
        sampler = settings.sampler();
        xs = new double[sampler.samplesPerPixel()];
        ys = new double[sampler.samplesPerPixel()];
        seed = settings.seed();
    }

    @Override
    public long render(Film film, TileRect tile, PixelLattice pixels, PixelLattice except) {
        long bad = 0;
        int step = pixels.step(), n = sampler.samplesPerPixel();
        for (int y = pixels.first(tile.y()); y < tile.y() + tile.height(); y += step) {
            for (int x = pixels.first(tile.x()); x < tile.x() + tile.width(); x += step) {
                if (except != null && except.contains(x, y)) {
                    continue;
                }
                random.reset(x, y, seed);
                sampler.generate(random, xs, ys);
                bad += tracer.trace(x, y, xs, ys, 0, n);
                samples += n;
                film.set(x, y, tracer.sumR / n, tracer.sumG / n, tracer.sumB / n);
            }
        }
        return bad;
    }

    @Override
    public long samples() {
        return samples;
    }
}
