// Starts the real jar on a free port for the browser tests, and stops it again.
import { spawn } from 'node:child_process';
import { createServer } from 'node:net';

/** A TCP port nobody listens on right now. */
export function freePort() {
  return new Promise((resolve, reject) => {
    const server = createServer();
    server.once('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => resolve(port));
    });
  });
}

/**
 * Runs `java -jar jar` on a free port (or on $E2E_PORT, for a machine where only some ports may be
 * used); resolves once /actuator/health says UP.
 */
export async function startServer(jar, { timeoutMs = 90_000 } = {}) {
  const port = process.env.E2E_PORT ? Number(process.env.E2E_PORT) : await freePort();
  const java = process.env.JAVA_HOME ? `${process.env.JAVA_HOME}/bin/java` : 'java';
  const child = spawn(java, ['-jar', jar, `--server.port=${port}`], { stdio: ['ignore', 'pipe', 'pipe'] });
  let log = '';
  child.stdout.on('data', (chunk) => (log += chunk));
  child.stderr.on('data', (chunk) => (log += chunk));
  const base = `http://127.0.0.1:${port}`;
  const deadline = Date.now() + timeoutMs;
  while (Date.now() < deadline) {
    if (child.exitCode !== null) throw new Error(`the server exited with ${child.exitCode}:\n${log}`);
    try {
      const response = await fetch(`${base}/actuator/health`);
      if (response.ok && (await response.json()).status === 'UP') {
        return { base, stop: () => stop(child), log: () => log };
      }
    } catch {
      // not listening yet
    }
    await new Promise((resolve) => setTimeout(resolve, 250));
  }
  stop(child);
  throw new Error(`the server did not become healthy within ${timeoutMs} ms:\n${log}`);
}

function stop(child) {
  if (child.exitCode === null) child.kill('SIGTERM');
}
