package touchline.bench;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * Benchmarks that check the issues' budgets; each measures a baseline in the same run. They live
 * outside the product (src/bench, compiled with the tests): nothing in src/main depends on them,
 * and {@code ./touchline bench ...} starts them through {@link #main}.
 */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = "Run a benchmark (figures go into docs/benchmarks.md).",
        subcommands = {
                IngestBenchCommand.class,
                UiBenchCommand.class,
                touchline.bench.record.RecordBenchmark.class,
                touchline.bench.record.ReplayBenchmark.class,
                NaoBenchCommand.class,
                GcBenchCommand.class,
                touchline.bench.serve.ServeBenchmark.class,
                StartBenchCommand.class,
                SubscriberCostBench.class,
                TagBenchCommand.class,
                PresentBenchCommand.class,
                Ros2DecodeBenchCommand.class,
                touchline.bench.bridges.BridgesBenchCommand.class,
        })
public final class BenchCommand implements Runnable {

    public static void main(String[] args) {
        System.exit(new CommandLine(new BenchCommand()).execute(args));
    }

    @Override
    public void run() {
        new CommandLine(this).usage(System.out);
    }
}
