package studio.server.system;

import org.springframework.boot.context.properties.ConfigurationProperties;
import org.springframework.boot.context.properties.bind.DefaultValue;

import studio.server.job.JobSettings;
import studio.server.scene.SceneLimits;

/**
 * The service's settings (application.properties, or environment variables such as
 * STUDIO_LIMITS_MAXWIDTH).
 *
 * @param concurrentRenders synchronous renders at once; more get 503 with Retry-After
 * @param renderThreads     worker threads per render, 0 for all cores
 */
@ConfigurationProperties("studio")
public record StudioProperties(Limits limits, Jobs jobs, @DefaultValue("2") int concurrentRenders,
                               @DefaultValue("0") int renderThreads) {

    /** Render jobs: how many run at once, how many wait, how long results are kept. */
    public record Jobs(@DefaultValue("1") int concurrent, @DefaultValue("8") int queue,
                       @DefaultValue("15m") java.time.Duration keepFinished, @DefaultValue("50") int maxFinished,
                       @DefaultValue("2m") java.time.Duration abandonAfter) {
    }

    /** Limits on one scene and one request. */
    public record Limits(@DefaultValue("4096") int maxWidth, @DefaultValue("4096") int maxHeight,
                         @DefaultValue("1024") int maxSamples, @DefaultValue("16") int maxDepth,
                         @DefaultValue("100000") int maxObjects, @DefaultValue("100") int maxLights,
                         @DefaultValue("2000000") int maxTriangles, @DefaultValue("33554432") long maxBodyBytes) {

        public SceneLimits toSceneLimits() {
            return new SceneLimits(maxWidth, maxHeight, maxSamples, maxDepth, maxObjects, maxLights, maxTriangles,
                    maxBodyBytes);
        }
    }

    /** The job settings, with this service's threads per render. */
    public JobSettings jobSettings() {
        return new JobSettings(jobs.concurrent(), jobs.queue(), jobs.keepFinished(), jobs.maxFinished(),
                jobs.abandonAfter(), renderThreads);
    }

    public StudioProperties {
        if (jobs == null) {
            JobSettings d = JobSettings.DEFAULTS;
            jobs = new Jobs(d.concurrent(), d.queue(), d.keepFinished(), d.maxFinished(), d.abandonAfter());
        }
        if (limits == null) {
            SceneLimits d = SceneLimits.DEFAULTS;
            limits = new Limits(d.maxWidth(), d.maxHeight(), d.maxSamples(), d.maxDepth(), d.maxObjects(),
                    d.maxLights(), d.maxTriangles(), d.maxBodyBytes());
        }
    }
}
