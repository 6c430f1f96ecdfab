package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/** Benchmarks that check the issues' budgets; each measures a baseline in the same run. */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = "Run a benchmark (figures go into docs/benchmarks.md).",
        subcommands = {
                IngestBenchCommand.class,
                UiBenchCommand.class,
                touchline.record.bench.RecordBenchmark.class,
                NaoBenchCommand.class,
                GcBenchCommand.class,
                touchline.serve.bench.ServeBenchmark.class,
        })
final class BenchCommand implements Runnable {

    @Override
    public void run() {
        new CommandLine(this).usage(System.out);
    }
}
