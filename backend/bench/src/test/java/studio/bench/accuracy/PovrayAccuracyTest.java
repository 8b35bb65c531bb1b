package studio.bench.accuracy;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;

class PovrayAccuracyTest {

    /** The end of POV-Ray 3.7's statistics: parse, bounding and trace times, each with its CPU seconds. */
    private static final String STATS = """
            Parser Time
              Parse Time:       0 hours  0 minutes  0 seconds (0.004 seconds)
                          using 1 thread(s) with 0.003 CPU-seconds total
              Bounding Time:    0 hours  0 minutes  0 seconds (0.001 seconds)
                          using 1 thread(s) with 0.002 CPU-seconds total
            ----------------------------------------------------------------------------
            Render Time:
              Photon Time:      No photons
              Radiosity Time:   No radiosity
              Trace Time:       0 hours  0 minutes  1 seconds (1.234 seconds)
                          using 2 thread(s) with 2.405 CPU-seconds total
            POV-Ray finished
            """;

    @Test
    void theTraceTimeAndItsCpuSecondsAreReadNotTheParsersBeforeThem() throws IOException {
        assertThat(PovrayAccuracy.number(PovrayAccuracy.TRACE_TIME, STATS, Path.of("stats"))).isEqualTo(1.234);
        assertThat(PovrayAccuracy.number(PovrayAccuracy.CPU_TIME, STATS, Path.of("stats"))).isEqualTo(2.405);
    }

    @Test
    void softLightSettingsCoverEachAreaLightVariantAtEachGrid() {
        List<PovrayAccuracy.Setting> settings = PovrayAccuracy.areaSettings();

        assertEquals(4 * PovrayAccuracy.AREA_GRID.length, settings.size());
        assertEquals(List.of("povray-area", "povray-area-jitter", "povray-area-adaptive", "povray-area-adaptive-jitter"),
                settings.stream().map(PovrayAccuracy.Setting::method).distinct().toList());
        assertEquals(List.of(2, 4, 8, 16), settings.stream().filter(s -> s.method().equals("povray-area-adaptive-jitter"))
                .map(s -> s.area().grid()).toList());
        assertTrue(PovrayAccuracy.settings().stream().allMatch(s -> s.area() == null));
    }
}
