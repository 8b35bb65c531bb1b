package studio.bench.accuracy;

/**
 * One row of the benchmark: a method at one setting on one scene.
 *
 * @param samples             samples per pixel asked for (the maximum, for adaptive sampling)
 * @param meanSamplesPerPixel samples traced per pixel on average
 * @param medianMillis        median wall time of Renderer.render over the runs
 * @param medianCpuMillis     median CPU time of the same renders (their threads' own clocks, tile by tile,
 *                            {@code RenderResult.cpuNanos}); NaN where not measured (POV-Ray's runs)
 * @param rmse                against the reference, over all channels in linear light
 * @param psnr                dB, peak 1.0 in linear light
 * @param threshold           the adaptive threshold, NaN for a fixed count
 */
record Measurement(String scene, String method, int samples, double meanSamplesPerPixel, double medianMillis,
                   double medianCpuMillis, double rmse, double psnr, double threshold) {
}
