package studio.server.system;

import org.springframework.boot.health.contributor.Health;
import org.springframework.boot.health.contributor.HealthIndicator;

/**
 * The memory budget in GET /actuator/health, as the component {@code renderMemory}: its capacity
 * and the bytes reserved and free now. It is always UP: a full budget means the server is busy
 * (new work gets 503 or 429 with Retry-After), not that it is unwell.
 */
final class RenderMemoryHealth implements HealthIndicator {

    private final MemoryBudget budget;

    RenderMemoryHealth(MemoryBudget budget) {
        this.budget = budget;
    }

    @Override
    public Health health() {
        long capacity = budget.capacity();
        long reserved = budget.reserved();
        return Health.up()
                .withDetail("capacityBytes", capacity)
                .withDetail("reservedBytes", reserved)
                .withDetail("freeBytes", Math.max(0, capacity - reserved))
                .build();
    }
}
