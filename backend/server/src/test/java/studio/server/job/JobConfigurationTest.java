package studio.server.job;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.springframework.boot.context.properties.EnableConfigurationProperties;
import org.springframework.boot.test.context.runner.ApplicationContextRunner;

import studio.server.system.StudioProperties;

/** The job settings the service configures from studio.jobs.* and studio.render-threads. */
class JobConfigurationTest {

    private final ApplicationContextRunner context = new ApplicationContextRunner()
            .withUserConfiguration(Properties.class);

    @EnableConfigurationProperties(StudioProperties.class)
    static class Properties {
    }

    @Test
    void settingsLeftUnsetAreTheDefaultJobSettings() {
        context.run(started -> {
            StudioProperties properties = started.getBean(StudioProperties.class);
            assertThat(JobConfiguration.settings(properties)).isEqualTo(JobSettings.DEFAULTS);
            assertThat(properties.jobs().shutdownGrace()).isEqualTo(Duration.ofSeconds(20));
        });
    }

    @Test
    void settingsTakeTheRenderThreads() {
        context.withPropertyValues("studio.jobs.queue=3", "studio.render-threads=2").run(started -> {
            JobSettings settings = JobConfiguration.settings(started.getBean(StudioProperties.class));
            assertThat(settings.queue()).isEqualTo(3);
            assertThat(settings.renderThreads()).isEqualTo(2);
            assertThat(settings.concurrent()).isEqualTo(JobSettings.DEFAULTS.concurrent());
        });
    }
}
