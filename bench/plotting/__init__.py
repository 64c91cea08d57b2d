"""The plots of bench/plot, one module per results file (see bench/plot)."""
