package studio.engine.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

class RunsTest {

    @Test
    void coversEveryItemOnceInOrderInRunsOfAtMostTheLength() {
        for (int n : new int[] {0, 1, Runs.LENGTH - 1, Runs.LENGTH, Runs.LENGTH + 1, 10 * Runs.LENGTH + 7}) {
            List<Integer> items = new ArrayList<>();
            List<Integer> lengths = new ArrayList<>();
            Runs.over(n, (from, to) -> {
                lengths.add(to - from);
                for (int i = from; i < to; i++) {
                    items.add(i);
                }
            });
            assertEquals(n, items.size(), "items of " + n);
            for (int i = 0; i < n; i++) {
                assertEquals(i, items.get(i));
            }
            assertEquals((n + Runs.LENGTH - 1) / Runs.LENGTH, lengths.size(), "runs of " + n);
            assertTrue(lengths.stream().allMatch(length -> length >= 1 && length <= Runs.LENGTH));
        }
    }
}
